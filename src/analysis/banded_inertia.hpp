#pragma once
/// \file
/// The number of eigenvalues of a symmetric matrix below a threshold without its eigenvalues:
/// the inertia of a shifted matrix by an LDLᵀ factorisation of its banded form.

#include <Eigen/Core>
#include <vector>

namespace cosserat::detail {

/// A symmetric m × m matrix of half-bandwidth b by its lower band: entry (i, j), 0 ≤ i − j ≤ b,
/// at lower(i, i − j).
struct SymmetricBand {
  Eigen::MatrixXd lower;  ///< m × (b + 1)
  int size() const { return static_cast<int>(lower.rows()); }
  int half_bandwidth() const { return static_cast<int>(lower.cols()) - 1; }
  /// Entry (i, j) for any i, j (zero outside the band).
  double operator()(int i, int j) const;
};

/// The number of eigenvalues of S below −below: the negative pivots of an LDLᵀ factorisation of
/// S + below · I (congruent, so of the same inertia: Sylvester's law), without pivoting:
/// O(m b²). −1 when a pivot is below 1e-10 of S's largest entry, where the factorisation without
/// pivoting can no longer be trusted (the caller then counts eigenvalues).
int CountEigenvaluesBelow(const SymmetricBand& S, double below);

/// The same for a dense symmetric S whose rows and columns taken in `order` (a permutation of
/// 0 … m − 1) make it banded.
int CountEigenvaluesBelow(const Eigen::MatrixXd& S, const std::vector<int>& order, double below);

}  // namespace cosserat::detail
