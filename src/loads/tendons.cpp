#include "cosserat/loads/tendons.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "cosserat/lie/so3.hpp"

namespace cosserat {

TendonRoute TendonRoute::Parallel(const Vec2& offset) { return Converging(offset, offset); }

TendonRoute TendonRoute::Converging(const Vec2& offset_base, const Vec2& offset_tip) {
  TendonRoute r;
  r.kind = Kind::kLinear;
  r.offset_base = offset_base;
  r.offset_tip = offset_tip;
  return r;
}

TendonRoute TendonRoute::Helical(double radius, double pitch, double phase) {
  TendonRoute r;
  r.kind = Kind::kHelical;
  r.radius = radius;
  r.pitch = pitch;
  r.phase = phase;
  return r;
}

Vec3 TendonRoute::OffsetAt(double s, double length) const {
  if (kind == Kind::kLinear) {
    const Vec2 r = offset_base + (s / length) * (offset_tip - offset_base);
    return Vec3(r.x(), r.y(), 0.0);
  }
  const double phi = phase + 2 * M_PI * s / pitch;
  return Vec3(radius * std::cos(phi), radius * std::sin(phi), 0.0);
}

Vec3 TendonRoute::OffsetRateAt(double s, double length) const {
  if (kind == Kind::kLinear) {
    const Vec2 d = (offset_tip - offset_base) / length;
    return Vec3(d.x(), d.y(), 0.0);
  }
  const double w = 2 * M_PI / pitch;
  const double phi = phase + w * s;
  return Vec3(-radius * w * std::sin(phi), radius * w * std::cos(phi), 0.0);
}

double TendonRoute::MaxOffset() const {
  return kind == Kind::kLinear ? std::max(offset_base.norm(), offset_tip.norm()) : radius;
}

bool TendonRoute::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (kind == Kind::kLinear) {
    if (!offset_base.allFinite() || !offset_tip.allFinite()) return fail("offset must be finite");
    return true;
  }
  if (!(std::isfinite(radius) && radius > 0)) return fail("radius must be positive");
  if (!(std::isfinite(pitch) && pitch != 0)) return fail("pitch must be finite and non-zero");
  if (!std::isfinite(phase)) return fail("phase must be finite");
  return true;
}

TendonSample SampleTendons(const std::vector<Tendon>& tendons, double s, double length) {
  TendonSample out;
  out.count = static_cast<int>(tendons.size());
  for (int i = 0; i < out.count; ++i) {
    out.offset[i] = tendons[i].route.OffsetAt(s, length);
    out.offset_rate[i] = tendons[i].route.OffsetRateAt(s, length);
  }
  return out;
}

namespace {

Vec3 PathTangent(const TendonSample& sample, int i, const Vec6& xi) {
  return xi.tail<3>() + xi.head<3>().cross(sample.offset[i]) + sample.offset_rate[i];
}

}  // namespace

double TendonPathRate(const TendonSample& sample, int i, const Vec6& xi) {
  return PathTangent(sample, i, xi).norm();
}

Vec6 TendonWrench(const TendonSample& sample, const double* tension, const Vec6& xi, Mat6* d_xi,
                  std::array<Vec6, Actuation::kMaxTendons>* a) {
  Vec6 total = Vec6::Zero();
  if (d_xi) d_xi->setZero();
  for (int i = 0; i < sample.count; ++i) {
    const Vec3& r = sample.offset[i];
    const Vec3 q = PathTangent(sample, i, xi);
    const double q_norm = q.norm();
    const Vec3 t = q / q_norm;
    Vec6 a_i;
    a_i << r.cross(t), t;
    if (a) (*a)[i] = a_i;
    const double tau = tension[i];
    if (tau == 0.0) continue;
    total += tau * a_i;
    if (d_xi) {
      // dt = (I − t tᵀ)/|q| dq,  dq = dΓ − r × dK  ⇒  dt/dξ = P [−r̂, I] / |q|
      const Mat3 P = (Mat3::Identity() - t * t.transpose()) / q_norm;
      Eigen::Matrix<double, 3, 6> dt;
      dt << -P * lie::hat(r), P;
      d_xi->topRows<3>() += tau * lie::hat(r) * dt;
      d_xi->bottomRows<3>() += tau * dt;
    }
  }
  return total;
}

bool SolveTendonStrain(const Mat6& stiffness, const Vec6& rest_strain, const TendonSample& sample,
                       const double* tension, const Vec6& W, Vec6* xi, Mat6* H) {
  // Simplified Newton on g(ξ) = K (ξ − ξ*) + T(ξ) − W, with the matrix K + ∂T/∂ξ of the first
  // iterate factorised once. T is a small perturbation of the elastic law (∂T/∂ξ relative to K
  // is of order τ r²/EI and τ/EA, a few % at most), and it changes little between the guess (the
  // neighbouring stage's strain) and the solution, so each iteration contracts the error by
  // far more than the 1e-12 tolerance needs: a step below 1e-12 (relative) is the last one. Each
  // further iteration costs one evaluation of T, without its derivative or a factorisation.
  Mat6 dT;
  Vec6 g = stiffness * (*xi - rest_strain) + TendonWrench(sample, tension, *xi, &dT) - W;
  const Eigen::PartialPivLU<Mat6> lu(Mat6(stiffness + dT));
  for (int it = 0; it < 12; ++it) {
    const Vec6 step = lu.solve(g);
    *xi -= step;
    if (!xi->allFinite()) return false;
    if (step.norm() <= 1e-12 * (1.0 + xi->norm())) {
      // The tangent dξ = H⁻¹ dW needs the derivative at the solution, not at the first iterate.
      if (H) {
        TendonWrench(sample, tension, *xi, &dT);
        *H = stiffness + dT;
      }
      return true;
    }
    g = stiffness * (*xi - rest_strain) + TendonWrench(sample, tension, *xi) - W;
  }
  return false;
}

}  // namespace cosserat
