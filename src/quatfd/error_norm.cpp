#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cosserat/quatfd/integrator.hpp"

namespace cosserat::quatfd {
namespace {

// |err_i| / (atol + rel_tol max(|y_i|, |y_new_i|)): one component against its tolerance.
double Scaled(const Eigen::Ref<const Eigen::VectorXd>& y,
              const Eigen::Ref<const Eigen::VectorXd>& y_new,
              const Eigen::Ref<const Eigen::VectorXd>& err, int i, double atol, double rel_tol) {
  return std::abs(err[i]) / (atol + rel_tol * std::max(std::abs(y[i]), std::abs(y_new[i])));
}

// Im(ā b) for quaternions [w, x, y, z].
Eigen::Vector3d ImConjProduct(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  const Eigen::Vector3d av = a.tail<3>(), bv = b.tail<3>();
  return a[0] * bv - b[0] * av - av.cross(bv);
}

}  // namespace

double ErrorNorm(const IntegratorOptions& o, int n, const Eigen::Ref<const Eigen::VectorXd>& y,
                 const Eigen::Ref<const Eigen::VectorXd>& y_new,
                 const Eigen::Ref<const Eigen::VectorXd>& err) {
  double e = 0.0;
  for (int i = 0; i < 2 * n; ++i)
    e = std::max(e, Scaled(y, y_new, err, i, i < n ? o.abs_tol : o.velocity_abs_tol, o.rel_tol));
  return e;
}

double RotationErrorNorm(const IntegratorOptions& o, const QuatFdLayout& layout,
                         const Eigen::Ref<const Eigen::VectorXd>& y,
                         const Eigen::Ref<const Eigen::VectorXd>& y_new,
                         const Eigen::Ref<const Eigen::VectorXd>& err) {
  const int n = layout.size();
  double e = 0.0;
  for (int v = 0; v <= layout.segments; ++v)
    for (int i = QuatFdLayout::X(v); i < QuatFdLayout::X(v) + 3; ++i) {
      e = std::max(e, Scaled(y, y_new, err, i, o.abs_tol, o.rel_tol));
      e = std::max(e, Scaled(y, y_new, err, n + i, o.velocity_abs_tol, o.rel_tol));
    }
  const double rotation_scale = o.abs_tol + o.rel_tol;
  for (int s = 0; s < layout.segments; ++s) {
    const int i = QuatFdLayout::P(s);
    const Eigen::Vector4d p = y_new.segment<4>(i), pd = y_new.segment<4>(n + i);
    const Eigen::Vector4d dp = err.segment<4>(i), dpd = err.segment<4>(n + i);
    const double ip2 = 1.0 / p.squaredNorm();
    const Eigen::Vector3d omega = 2 * ip2 * ImConjProduct(p, pd);
    // δθ = 2 Im(p̄ δp)/|p|²; δω = [2 Im(δp̄ ṗ + p̄ δṗ) − 2 (p·δp) ω]/|p|². A radial δp or δṗ
    // (∥ p) gives δθ = 0 and δω = 0 (δp only −(p·δp) ω, as the projection's rescaling of ṗ).
    const Eigen::Vector3d dtheta = 2 * ip2 * ImConjProduct(p, dp);
    const Eigen::Vector3d domega =
        ip2 * (2 * (ImConjProduct(dp, pd) + ImConjProduct(p, dpd)) - 2 * p.dot(dp) * omega);
    for (int k = 0; k < 3; ++k) {
      e = std::max(e, std::abs(dtheta[k]) / rotation_scale);
      e = std::max(e, std::abs(domega[k]) / (o.velocity_abs_tol + o.rel_tol * std::abs(omega[k])));
    }
  }
  return e;
}

}  // namespace cosserat::quatfd
