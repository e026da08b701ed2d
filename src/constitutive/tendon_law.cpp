#include "cosserat/constitutive/tendon_law.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <limits>

#include "cosserat/lie/so3.hpp"

namespace cosserat {

namespace {

Vec3 PathTangent(const TendonSample& sample, int i, const Vec6& xi) {
  return xi.tail<3>() + xi.head<3>().cross(sample.offset[i]) + sample.offset_rate[i];
}

}  // namespace

double TendonPathRate(const TendonSample& sample, int i, const Vec6& xi) {
  return sample.ended[i] ? 0.0 : PathTangent(sample, i, xi).norm();
}

Vec6 TendonWrench(const TendonSample& sample, const double* tension, const Vec6& xi, Mat6* d_xi,
                  std::array<Vec6, Actuation::kMaxTendons>* a) {
  Vec6 total = Vec6::Zero();
  if (d_xi) d_xi->setZero();
  for (int i = 0; i < sample.count; ++i) {
    if (sample.ended[i]) {  // past its anchor: no tension, no derivative in it
      if (a) (*a)[i].setZero();
      continue;
    }
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
  // Newton on g(ξ) = K (ξ − ξ*) + T(ξ) − W, simplified: the matrix K + ∂T/∂ξ of the first
  // iterate is factorised and kept while each step shrinks to under kSlowContraction of the one
  // before. At moderate tension ∂T/∂ξ is a small part of K (τ r²/EI and τ/EA) and changes little
  // between the guess (the neighbouring stage's strain) and the solution, so the kept matrix
  // contracts far faster than the 1e-12 tolerance needs and each further iteration costs one
  // evaluation of T. A tendon pulled to τ r²/EI ≈ 0.3 (a helical route at 20 N on a 0.8 mm
  // spring-steel backbone) makes ∂T/∂ξ 30–40 % of K and the kept matrix stalls: a slower step
  // takes the derivative at the current iterate (Newton proper).
  constexpr int kMaxIterations = 40;
  constexpr double kSlowContraction = 0.25;
  Mat6 dT;
  Vec6 g = stiffness * (*xi - rest_strain) + TendonWrench(sample, tension, *xi, &dT) - W;
  Eigen::PartialPivLU<Mat6> lu(Mat6(stiffness + dT));
  double last = std::numeric_limits<double>::infinity();
  for (int it = 0; it < kMaxIterations; ++it) {
    const Vec6 step = lu.solve(g);
    *xi -= step;
    if (!xi->allFinite()) return false;
    const double size = step.norm();
    if (size <= 1e-12 * (1.0 + xi->norm())) {
      // The tangent dξ = H⁻¹ dW needs the derivative at the solution, not at the first iterate.
      if (H) {
        TendonWrench(sample, tension, *xi, &dT);
        *H = stiffness + dT;
      }
      return true;
    }
    const bool refresh = size > kSlowContraction * last;
    last = size;
    g = stiffness * (*xi - rest_strain) +
        TendonWrench(sample, tension, *xi, refresh ? &dT : nullptr) - W;
    if (refresh) lu.compute(Mat6(stiffness + dT));
  }
  return false;
}

}  // namespace cosserat
