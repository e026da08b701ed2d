#pragma once
/// \file
/// The Jacobian of the quaternion-FD model, ∂f/∂q and ∂f/∂v (banded, analytic), taken at one state
/// y_J and kept across Newton iterations and steps by the implicit integrators (SDIRK4, Radau
/// IIA), with the q it was taken at (the co-rotation turns it from there, corotation.hpp).

#include <Eigen/Core>

#include "cosserat/quatfd/banded_matrix.hpp"
#include "cosserat/quatfd/integrator.hpp"

namespace cosserat::quatfd {

struct FrozenJacobian {
  BandedMatrix dfdq, dfdv;
  Eigen::VectorXd q;   ///< where J was evaluated
  Eigen::VectorXd f;   ///< f there: the evaluation forms it anyway (without it, it allocates)
  bool valid = false;  ///< J has been evaluated at least once
  bool fresh = false;  ///< J was evaluated during the current step attempt (the caller clears it)

  /// Allocates for the model's size and band (no allocation afterwards).
  void Resize(const QuatFdModel& model);
  /// Evaluates J at y = [q; v]; counts it in stats. Sets valid and fresh.
  void Evaluate(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& y,
                IntegratorStats* stats);
};

}  // namespace cosserat::quatfd
