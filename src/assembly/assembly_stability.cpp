// The stability of an assembly's bodies at a static solution: their condensed stiffness, the
// Schur complement of the rods' block in the statics Jacobian (AssemblyStaticsSolver).
#include <Eigen/Eigenvalues>
#include <cmath>

#include "cosserat/assembly/assembly_statics.hpp"

namespace cosserat {

Eigen::MatrixXd AssemblyStaticsSolver::CondensedBodyStiffness(const StaticLoads& loads) {
  if (!has_solution_ || poses_.empty()) return Eigen::MatrixXd();
  mode_ = Mode::kForward;
  ShootAll();
  Eigen::MatrixXd J;
  Jacobian(loads, &J, nullptr);
  const int r = 6 * rod_count(), b = 6 * static_cast<int>(poses_.size());
  const Eigen::MatrixXd rods_on_bodies =
      J.topLeftCorner(r, r).partialPivLu().solve(J.topRightCorner(r, b));
  Eigen::MatrixXd K = J.bottomRightCorner(b, b) - J.bottomLeftCorner(b, r) * rods_on_bodies;
  // Moment rows in each body's frame, where its pose's rotation is measured (R Exp(δθ)): the
  // pairs (force_W, δp_W) and (moment_B, δθ_B) are conjugate, so the conservative part of K is
  // symmetric (the moment about the body's origin pairs with a turn about it).
  for (size_t q = 0; q < poses_.size(); ++q)
    K.middleRows(6 * q + 3, 3) = poses_[q].R.transpose() * K.middleRows(6 * q + 3, 3);
  return K;
}

int AssemblyStaticsSolver::BodyStabilityIndex(const StaticLoads& loads) {
  for (const RigidBody& body : assembly_.bodies)
    if (!body.moment_W.isZero(0.0)) return -1;
  const Eigen::MatrixXd K = CondensedBodyStiffness(loads);
  if (K.size() == 0 || !K.allFinite()) return -1;
  // Scaled by its diagonal, d K d with d = |diag K|^−½ (a congruence: the signs of a symmetric
  // K's eigenvalues are kept). Unscaled, a body's stiffnesses span N/m along a slender column
  // (EA/L) to N·m/rad across it (~EI/L), (L/r)² apart, and a bending mode's eigenvalue lies
  // below the round-off floor relative to the axial one: a column of wire (L/r = 1667) reads
  // stable at 1.2 times its Euler load.
  // A diagonal entry at round-off of the largest (a neutral direction, a turn about a
  // torsion-free tip's axis) is scaled as the largest is: scaled by itself, its sign would be
  // round-off's.
  const Eigen::VectorXd diagonal = K.diagonal().cwiseAbs();
  const double largest_entry = diagonal.maxCoeff() > 0 ? diagonal.maxCoeff() : 1.0;
  Eigen::VectorXd d(diagonal.size());
  for (Eigen::Index i = 0; i < d.size(); ++i)
    d(i) = 1.0 / std::sqrt(diagonal(i) > 1e-12 * largest_entry ? diagonal(i) : largest_entry);
  const Eigen::VectorXcd eig = (d.asDiagonal() * K * d.asDiagonal()).eigenvalues();
  const double largest = eig.cwiseAbs().maxCoeff();
  int unstable = 0;
  for (int k = 0; k < eig.size(); ++k) unstable += eig[k].real() > 1e-8 * largest;
  return unstable;
}

}  // namespace cosserat
