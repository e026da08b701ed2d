#include "banded_inertia.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cosserat::detail {

bool BandedLdlt::Factorize(const SymmetricBand& S, double shift, double floor) {
  const int m = S.size(), b = S.half_bandwidth();
  negative_ = 0;
  if (m == 0 || b < 0) return false;
  if (!S.lower.allFinite() || !std::isfinite(shift)) return false;
  band_ = Eigen::MatrixXd::Zero(m, b + 1);
  d_.resize(m);
  for (int k = 0; k < m; ++k) {
    double dk = S.lower(k, 0) + shift;
    for (int j = std::max(0, k - b); j < k; ++j) dk -= band_(k, k - j) * band_(k, k - j) * d_(j);
    if (!(std::abs(dk) > floor)) return false;
    d_(k) = dk;
    negative_ += dk < 0;
    for (int i = k + 1; i <= std::min(m - 1, k + b); ++i) {
      double lik = S.lower(i, i - k);
      for (int j = std::max(0, i - b); j < k; ++j) lik -= band_(i, i - j) * band_(k, k - j) * d_(j);
      band_(i, i - k) = lik / dk;
    }
  }
  return true;
}

void BandedLdlt::Solve(Eigen::Ref<Eigen::VectorXd> x) const {
  const int m = static_cast<int>(d_.size()), b = static_cast<int>(band_.cols()) - 1;
  for (int i = 0; i < m; ++i)  // L y = x
    for (int j = std::max(0, i - b); j < i; ++j) x(i) -= band_(i, i - j) * x(j);
  for (int i = 0; i < m; ++i) x(i) /= d_(i);  // D z = y
  for (int i = m - 1; i >= 0; --i)  // Lᵀ x = z
    for (int j = i + 1; j <= std::min(m - 1, i + b); ++j) x(i) -= band_(j, j - i) * x(j);
}

int CountEigenvaluesBelow(const SymmetricBand& S, double below) {
  const double size = S.lower.cwiseAbs().maxCoeff();
  if (!(size > 0)) return -1;
  BandedLdlt ldlt;
  return ldlt.Factorize(S, below, 1e-10 * size) ? ldlt.negative_pivots() : -1;
}

std::vector<int> AlongTheRod(const std::vector<int>& vertex_column,
                             const std::vector<int>& segment_column, int m) {
  std::vector<long> rank(m, -1);
  for (size_t n = 0; n < vertex_column.size(); ++n)
    if (vertex_column[n] >= 0)
      for (int k = 0; k < 3; ++k) rank[vertex_column[n] + k] = 3 * (2 * static_cast<long>(n)) + k;
  for (size_t nu = 0; nu < segment_column.size(); ++nu)
    for (int k = 0; k < 3; ++k)
      rank[segment_column[nu] + k] = 3 * (2 * static_cast<long>(nu) + 1) + k;
  if (std::find(rank.begin(), rank.end(), -1) != rank.end()) return {};
  std::vector<int> order(m);
  for (int i = 0; i < m; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return rank[a] < rank[b]; });
  return order;
}

SymmetricBand BandInOrder(const Eigen::SparseMatrix<double>& S, const std::vector<int>& order) {
  const int m = static_cast<int>(order.size());
  std::vector<int> position(m);
  for (int i = 0; i < m; ++i) position[order[i]] = i;
  int b = 0;
  for (int j = 0; j < S.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it)
      if (it.value() != 0.0) b = std::max(b, std::abs(position[it.row()] - position[it.col()]));
  SymmetricBand band{Eigen::MatrixXd::Zero(m, b + 1)};
  for (int j = 0; j < S.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it) {
      const int pi = position[it.row()], pj = position[it.col()];
      // Stored zeros may lie outside the band measured above: skipped, not written past it.
      if (pi >= pj && it.value() != 0.0) band.lower(pi, pi - pj) = it.value();
    }
  return band;
}

}  // namespace cosserat::detail
