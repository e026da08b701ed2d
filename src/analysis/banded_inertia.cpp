#include "banded_inertia.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cosserat::detail {

double SymmetricBand::operator()(int i, int j) const {
  if (i < j) std::swap(i, j);
  return i - j <= half_bandwidth() ? lower(i, i - j) : 0.0;
}

int CountEigenvaluesBelow(const SymmetricBand& S, double below) {
  const int m = S.size(), b = S.half_bandwidth();
  if (m == 0 || b < 0) return -1;
  const double size = S.lower.cwiseAbs().maxCoeff();
  if (!(size > 0) || !std::isfinite(size)) return -1;
  // L (unit lower triangular) in the same band storage: L(i, j) at band(i, i − j).
  Eigen::MatrixXd band = Eigen::MatrixXd::Zero(m, b + 1);
  Eigen::VectorXd d(m);
  int negative = 0;
  for (int k = 0; k < m; ++k) {
    double dk = S.lower(k, 0) + below;
    for (int j = std::max(0, k - b); j < k; ++j) dk -= band(k, k - j) * band(k, k - j) * d(j);
    if (!(std::abs(dk) > 1e-10 * size)) return -1;
    d(k) = dk;
    negative += dk < 0;
    for (int i = k + 1; i <= std::min(m - 1, k + b); ++i) {
      double lik = S.lower(i, i - k);
      for (int j = std::max(0, i - b); j < k; ++j) lik -= band(i, i - j) * band(k, k - j) * d(j);
      band(i, i - k) = lik / dk;
    }
  }
  return negative;
}

int CountEigenvaluesBelow(const Eigen::MatrixXd& S, const std::vector<int>& order, double below) {
  const int m = static_cast<int>(order.size());
  if (m == 0 || S.rows() != m || S.cols() != m) return -1;
  auto at = [&](int i, int j) { return S(order[i], order[j]); };
  int b = 0;  // the half-bandwidth in this order
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j)
      if (at(i, j) != 0.0) b = std::max(b, i - j);
  SymmetricBand band{Eigen::MatrixXd::Zero(m, b + 1)};
  for (int i = 0; i < m; ++i)
    for (int j = std::max(0, i - b); j <= i; ++j) band.lower(i, i - j) = at(i, j);
  return CountEigenvaluesBelow(band, below);
}

}  // namespace cosserat::detail
