#pragma once
/// \file
/// The number of eigenvalues of a symmetric matrix below a threshold without its eigenvalues:
/// the inertia of a shifted matrix by an LDLᵀ factorisation of its banded form.

#include <Eigen/Core>
#include <vector>

namespace cosserat::detail {

/// The number of eigenvalues of the symmetric matrix S below −below: the negative pivots of an
/// LDLᵀ factorisation of S + below · I (congruent, so of the same inertia: Sylvester's law),
/// without pivoting, its rows and columns taken in `order` (a permutation of 0 … m − 1 that
/// makes it banded, half-bandwidth b): O(m b²). −1 when a pivot is below 1e-10 of S's largest
/// entry, where the factorisation without pivoting can no longer be trusted (the caller then
/// counts eigenvalues).
int CountEigenvaluesBelow(const Eigen::MatrixXd& S, const std::vector<int>& order, double below);

}  // namespace cosserat::detail
