#pragma once
/// \file
/// A symmetric banded matrix, its LDLᵀ factorisation without pivoting, and from it the number of
/// its eigenvalues below a threshold (its inertia, by Sylvester's law) without its eigenvalues.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace cosserat::detail {

/// A symmetric m × m matrix of half-bandwidth b by its lower band: entry (i, j), 0 ≤ i − j ≤ b,
/// at lower(i, i − j).
struct SymmetricBand {
  Eigen::MatrixXd lower;  ///< m × (b + 1)
  int size() const { return static_cast<int>(lower.rows()); }
  int half_bandwidth() const { return static_cast<int>(lower.cols()) - 1; }
};

/// S + shift · I = L D Lᵀ, L unit lower triangular in S's band, without pivoting: O(m b²), then
/// solves in O(m b). Without pivoting it is reliable where it is definite (Demmel & Veselić 1992:
/// accurate relative to the diagonal), and its pivots' signs count eigenvalues anywhere but near
/// a singular shift, which Factorize refuses.
class BandedLdlt {
 public:
  /// False when a pivot's magnitude is not above `floor` (the shift is too near an eigenvalue)
  /// or S is not finite: then neither negative_pivots() nor Solve() is valid.
  bool Factorize(const SymmetricBand& S, double shift, double floor);
  /// The pivots below zero: the eigenvalues of S below −shift.
  int negative_pivots() const { return negative_; }
  /// x ← (S + shift I)⁻¹ x.
  void Solve(Eigen::Ref<Eigen::VectorXd> x) const;

 private:
  Eigen::MatrixXd band_;  ///< L(i, j) at band_(i, i − j), 1 ≤ i − j ≤ b
  Eigen::VectorXd d_;
  int negative_ = 0;
};

/// The number of eigenvalues of S below −below: the negative pivots of an LDLᵀ factorisation of
/// S + below · I (congruent, so of the same inertia). −1 where a pivot is below 1e-10 of S's
/// largest entry, where the factorisation without pivoting can no longer be trusted to count
/// (the caller then counts eigenvalues).
int CountEigenvaluesBelow(const SymmetricBand& S, double below);

/// The order along the rod of m tangent coordinates, three per free vertex and three per
/// segment (vertex n before segment n before vertex n + 1), in which a quaternion-FD stiffness,
/// whose coordinates couple only with their neighbours', is banded. vertex_column[n]: the first
/// of vertex n's (−1 when it is prescribed); segment_column[ν]: segment ν's. Empty when some
/// coordinate is neither.
std::vector<int> AlongTheRod(const std::vector<int>& vertex_column,
                             const std::vector<int>& segment_column, int m);

/// The sparse symmetric S in the order `order` (a permutation of 0 … m − 1) that makes it
/// banded: row i of the band is row order[i] of S.
SymmetricBand BandInOrder(const Eigen::SparseMatrix<double>& S, const std::vector<int>& order);

}  // namespace cosserat::detail
