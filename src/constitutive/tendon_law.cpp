#include "cosserat/constitutive/tendon_law.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

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
