#include "banded_inertia.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat::detail {

int CountEigenvaluesBelow(const Eigen::MatrixXd& S, const std::vector<int>& order, double below) {
  const int m = static_cast<int>(order.size());
  if (m == 0 || S.rows() != m || S.cols() != m) return -1;
  auto at = [&](int i, int j) { return S(order[i], order[j]) + (i == j ? below : 0.0); };
  // The half-bandwidth in this order.
  int b = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j)
      if (at(i, j) != 0.0) b = std::max(b, i - j);
  const double size = S.cwiseAbs().maxCoeff();
  if (!(size > 0) || !std::isfinite(size)) return -1;
  // L (unit lower triangular) in band storage: L(i, j) at band(i, i − j), 1 ≤ i − j ≤ b.
  Eigen::MatrixXd band = Eigen::MatrixXd::Zero(m, b + 1);
  Eigen::VectorXd d(m);
  int negative = 0;
  for (int k = 0; k < m; ++k) {
    double dk = at(k, k);
    for (int j = std::max(0, k - b); j < k; ++j) dk -= band(k, k - j) * band(k, k - j) * d(j);
    if (!(std::abs(dk) > 1e-10 * size)) return -1;
    d(k) = dk;
    negative += dk < 0;
    for (int i = k + 1; i <= std::min(m - 1, k + b); ++i) {
      double lik = at(i, k);
      for (int j = std::max(0, i - b); j < k; ++j) lik -= band(i, i - j) * band(k, k - j) * d(j);
      band(i, i - k) = lik / dk;
    }
  }
  return negative;
}

}  // namespace cosserat::detail
