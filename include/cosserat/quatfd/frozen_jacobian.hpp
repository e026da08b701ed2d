#pragma once
/// \file
/// The Jacobian of the quaternion-FD model, ∂f/∂q and ∂f/∂v (banded, analytic), taken at one state
/// y_J and kept across Newton iterations and steps by the implicit integrators (SDIRK4, Radau
/// IIA), with the q it was taken at (the co-rotation turns it from there, corotation.hpp); and
/// the second-order reduction of their linear systems, which the Rosenbrock integrator shares.
///
/// Reduction: for y = [q; v] and J = [[0, I], [A, B]] (A = ∂f/∂q, B = ∂f/∂v), the 2n × 2n system
/// (aI − J) x = r is
///   (a² I − a B − A) x_v = a r_v + A r_q,  x_q = (r_q + x_v)/a,
/// one banded n × n system of bandwidth QuatFdLayout::kBandwidth: the second-order structure that
/// the stiff solvers Lang & Linn use are adapted to.

#include <Eigen/Core>

#include "cosserat/numerics/banded_matrix.hpp"
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

  /// m ← a² I − a B − A (m sized as dfdq): the matrix of the reduced system for the shift a.
  void AssembleShifted(double a, BandedMatrix* m) const;
  /// (aI − J) x = r in place on r = [r_q; r_v], with m = AssembleShifted(a) factorised;
  /// acc: n entries of scratch.
  void SolveShifted(double a, const BandedMatrix& m, Eigen::Ref<Eigen::VectorXd> r,
                    Eigen::Ref<Eigen::VectorXd> acc) const;
};

}  // namespace cosserat::quatfd
