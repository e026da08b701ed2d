#pragma once
/// \file
/// A stiff, linearly implicit Rosenbrock integrator for q̇ = v, v̇ = f(q, v) with the model's
/// exact banded Jacobian, so one step is O(N).
///
/// Method: the L-stable 4th-order Rosenbrock scheme with an embedded 3rd-order error estimate of
/// Boost.Odeint's rosenbrock4 (Hairer–Wanner's RODAS coefficients, 6 evaluations of f and one
/// Jacobian per step), in the same "g" form: (I/(γh) − J) g_i = F(y_i) + Σ c_ij g_j / h.
/// For J = [[0, I], [A, B]] (A = ∂f/∂q, B = ∂f/∂v) the 2n × 2n system reduces to one banded
/// n × n system (Lang & Linn 2009: solvers "adapted to second order differential equations"):
///   (a² I − a B − A) w = a r_v + A r_q,  u = (r_q + w)/a,  a = 1/(γh),
/// with bandwidth 10; its LU (partial pivoting) is computed once per step. The model's clock
/// (a gusting flow) stays at the step's start for all stages: without RODAS's stage times and
/// ∂f/∂t term, loads that change in time are first order here; the runs use Radau IIA.

#include <Eigen/Core>

#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/frozen_jacobian.hpp"
#include "cosserat/quatfd/integrator.hpp"

namespace cosserat::quatfd {

class RosenbrockIntegrator final : public AdaptiveIntegrator {
 public:
  /// Allocates every buffer; Advance() does not allocate.
  RosenbrockIntegrator(const QuatFdModel& model, const IntegratorOptions& options = {});

  const char* name() const override { return "rosenbrock4-banded"; }

  /// One step of size h from y = [q; v] without error control: writes y_new and the error
  /// estimate (the same components). Returns false when the iteration matrix is singular. Public
  /// for the cross-check against Boost.Odeint's dense rosenbrock4.
  bool Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h, Eigen::Ref<Eigen::VectorXd> y_new,
            Eigen::Ref<Eigen::VectorXd> error);

 private:
  Trial TryStep(double h) override;
  double Rejected(double h, const Trial& trial) override;
  double Accepted(double h, double err) override;
  /// (I/(γh) − J) g = r for r = rhs (in place).
  void SolveStage(Eigen::Ref<Eigen::VectorXd> rhs);

  double a_ = 0;        ///< 1/(γ h)
  FrozenJacobian jac_;  ///< evaluated at the start of every step
  BandedMatrix M_;      ///< a² I − a B − A
  Eigen::VectorXd g_[5], tmp_, acc_;
};

}  // namespace cosserat::quatfd
