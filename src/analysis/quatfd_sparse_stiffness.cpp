/// \file
/// The analytic static stiffness of the quaternion-FD model as a sparse matrix: built from the
/// banded ∂f/∂q column by column over its band only, O(N) in time and memory.

#include <Eigen/SparseCore>
#include <algorithm>

#include "cosserat/analysis/quatfd_buckling.hpp"

namespace cosserat {

namespace {
using Layout = quatfd::QuatFdLayout;
}  // namespace

Eigen::SparseMatrix<double> QuatFdBuckling::StiffnessAnalyticSparse(const Eigen::VectorXd& q) {
  const int N = model_.layout().segments;
  const int nv = static_cast<int>(free_vertices_.size());
  const int m = 3 * nv + 3 * N, n = model_.size();
  const double L = model_.length(), scale = -1.0 / model_.moment_scale();
  model_.Jacobian(q, zero_v_, 0.0, 0.0, &dfdq_, &dfdv_, nullptr);
  const BandedMatrix& A = dfdq_;
  const std::vector<double>& mass = model_.vertex_mass();
  // Per model row that starts a free vertex's position: that vertex's index among the free ones.
  std::vector<int> free_index(N + 1, -1);
  for (int a = 0; a < nv; ++a) free_index[free_vertices_[a]] = a;

  // Column j is ∂f/∂q along tangent coordinate j (δx = L e_k; δp = ½ p ⊗ [0, e_k]), non-zero
  // only on rows [r0, r1] of the band; its rows in the tangent coordinates are, as in the dense
  // build, forces m ∂f_x (times L) and torques 2 J Im(p̄ ⊗ ∂f_p).
  Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Triplet<double>> entries;
  auto add = [&](int i, int j, double value) {
    if (value != 0.0) entries.emplace_back(i, j, scale * value);
  };
  for (int j = 0; j < m; ++j) {
    int c0;
    Vec4 weight = Vec4::Zero();
    if (j < 3 * nv) {
      c0 = Layout::X(free_vertices_[j / 3]) + j % 3;
      weight[0] = L;
    } else {
      const int s = (j - 3 * nv) / 3, k = (j - 3 * nv) % 3;
      c0 = Layout::P(s);
      Vec4 e = Vec4::Zero();
      e[1 + k] = 1.0;
      weight = 0.5 * lie::QuatMultiply<double>(q.segment<4>(c0), e);
    }
    const int c1 = j < 3 * nv ? c0 : c0 + 3;
    const int r0 = std::max(0, c0 - A.upper()), r1 = std::min(n - 1, c1 + A.lower());
    for (int r = r0; r <= r1; ++r) {
      double sum = 0.0;
      for (int c = c0; c <= c1; ++c)
        if (A.InBand(r, c)) sum += weight[c - c0] * A(r, c);
      column[r] = sum;
    }
    // The vertices and segments whose rows meet [r0, r1].
    const int first = std::max(0, r0 / 7 - 1), last = std::min(N, r1 / 7 + 1);
    for (int v = first; v <= last; ++v) {
      const int a = free_index[v];
      if (a < 0) continue;
      for (int k = 0; k < 3; ++k)
        add(3 * a + k, j, L * mass[v] * column[Layout::X(v) + k]);
    }
    for (int s = first; s <= std::min(N - 1, last); ++s) {
      const Vec4 p = q.segment<4>(Layout::P(s)) / q.segment<4>(Layout::P(s)).squaredNorm();
      const Vec3 w = 2.0 * quatfd::kernels::ImConjMul<double>(p, column.segment<4>(Layout::P(s)));
      const Vec3& J = model_.segment_inertia(s);
      for (int k = 0; k < 3; ++k) add(3 * nv + 3 * s + k, j, J[k] * w[k]);
    }
    column.segment(r0, r1 - r0 + 1).setZero();
  }
  Eigen::SparseMatrix<double> H(m, m);
  H.setFromTriplets(entries.begin(), entries.end());
  return H;
}

}  // namespace cosserat
