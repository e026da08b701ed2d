#include "quatfd_reduction.hpp"

#include <cmath>

#include "cosserat/lie/quaternion.hpp"

namespace cosserat::detail {

Mat3 VertexMassBlock::Power(double e) const {
  const Mat3 tt = t * t.transpose();
  return std::pow(mass + added, e) * (Mat3::Identity() - tt) + std::pow(mass, e) * tt;
}

Reduction Reduce(const quatfd::QuatFdModel& model, const Eigen::VectorXd& q) {
  using L = quatfd::QuatFdLayout;
  const int N = model.layout().segments, n_full = model.size();
  Reduction red;
  std::vector<Eigen::Triplet<double>> t, p;
  std::vector<double> mass;
  int m = 0;
  for (int n = 0; n <= N; ++n) {
    red.vertex_column.push_back(model.IsFixed(L::X(n)) ? -1 : m);
    if (!model.IsFixed(L::X(n))) {
      for (int k = 0; k < 3; ++k) {
        t.emplace_back(L::X(n) + k, m + k, 1.0);
        p.emplace_back(m + k, L::X(n) + k, 1.0);
        mass.push_back(model.vertex_mass()[n]);
      }
      if (const double ma = model.vertex_added_mass(n); ma > 0)
        red.mass_blocks.push_back({m, model.vertex_mass()[n], ma, model.VertexDirection(q, n)});
      m += 3;
    }
    if (n == N) break;
    red.segment_column.push_back(m);
    const Vec4 pq = q.segment<4>(L::P(n));
    const Vec4 pbar = lie::QuatConjugate(pq);
    for (int k = 0; k < 3; ++k) {
      // δp = ½ p ⊗ [0; e_k]  (a body-frame rotation by θ_k: R(p + δp) = R(p) Exp(θ))
      Vec4 e = Vec4::Zero();
      e(k + 1) = 1.0;
      const Vec4 col = 0.5 * lie::QuatMultiply(pq, e);
      for (int j = 0; j < 4; ++j) t.emplace_back(L::P(n) + j, m + k, col(j));
      // θ = 2 Im(p̄ ⊗ δp) / |p|² (|p| = 1 after the projection)
      Vec4 ej = Vec4::Zero();
      for (int j = 0; j < 4; ++j) {
        ej.setZero();
        ej(j) = 1.0;
        p.emplace_back(m + k, L::P(n) + j, 2.0 * lie::QuatMultiply(pbar, ej)(k + 1));
      }
      mass.push_back(model.segment_inertia(n)(k));
    }
    m += 3;
  }
  red.T.resize(n_full, m);
  red.T.setFromTriplets(t.begin(), t.end());
  red.P.resize(m, n_full);
  red.P.setFromTriplets(p.begin(), p.end());
  red.mass = Eigen::Map<const Eigen::VectorXd>(mass.data(), m);
  return red;
}

Eigen::MatrixXd MassTimes(const Reduction& red, const Eigen::VectorXd& diagonal, double e,
                          const Eigen::MatrixXd& X) {
  Eigen::MatrixXd Y = diagonal.asDiagonal() * X;
  for (const VertexMassBlock& b : red.mass_blocks)
    Y.middleRows<3>(b.column) = b.Power(e) * X.middleRows<3>(b.column);
  return Y;
}

Eigen::MatrixXd TimesMass(const Reduction& red, const Eigen::VectorXd& diagonal, double e,
                          const Eigen::MatrixXd& X) {
  Eigen::MatrixXd Y = X * diagonal.asDiagonal();
  for (const VertexMassBlock& b : red.mass_blocks)
    Y.middleCols<3>(b.column) = X.middleCols<3>(b.column) * b.Power(e);
  return Y;
}

}  // namespace cosserat::detail
