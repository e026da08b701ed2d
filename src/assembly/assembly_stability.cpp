// The stability of an assembly's bodies at a static solution: their condensed stiffness, the
// Schur complement of the rods' block in the statics Jacobian (AssemblyStaticsSolver).
#include <Eigen/Eigenvalues>

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
  const Eigen::VectorXcd eig = K.eigenvalues();
  const double largest = eig.cwiseAbs().maxCoeff();
  int unstable = 0;
  for (int k = 0; k < eig.size(); ++k) unstable += eig[k].real() > 1e-8 * largest;
  return unstable;
}

}  // namespace cosserat
