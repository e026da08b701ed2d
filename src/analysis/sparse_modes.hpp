#pragma once
// The lowest quaternion-FD modes of a large grid without the dense spectrum: subspace iteration
// on the banded factorisation of the mass-scaled stiffness. Internal to src/analysis.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "quatfd_reduction.hpp"

namespace cosserat::detail {

/// The reduced mass M (its diagonal and the 3×3 vertex blocks of an added mass) to the power e,
/// as a sparse matrix.
Eigen::SparseMatrix<double> SparseMassPower(const Reduction& red, double e);

/// The `count` lowest ω² (rad²/s², ascending) of K φ = ω² M φ for the symmetric reduced
/// stiffness K, with the reduced shapes φ = M^−½ ψ when `shapes`: subspace iteration with
/// Rayleigh–Ritz on H⁻¹, H = M^−½ K M^−½ factorised banded (BandedLdlt), whose largest
/// eigenvalues 1/ω² are the lowest modes and keep their digits as the inverse spectrum's do;
/// then Sylvester's law checks that no eigenvalue below the last one found was missed. False,
/// leaving *eig empty, when H is not positive definite (an unstable equilibrium), the iteration
/// stalls or the check fails: the caller then takes the dense spectrum.
bool LowestModesSparse(const Eigen::SparseMatrix<double>& K, const Reduction& red, int count,
                       bool shapes, std::vector<std::pair<double, Eigen::VectorXd>>* eig);

}  // namespace cosserat::detail
