#pragma once
/// \file
/// A stiff, fully implicit integrator for q̇ = v, v̇ = f(q, v) of the quaternion-FD rod: the
/// L-stable, stiffly accurate 5-stage SDIRK method of order 4 with an embedded order-3 estimate
/// (Hairer & Wanner, Solving ODEs II, Table IV.6.5 "SDIRK4", γ = 1/4), with simplified Newton
/// iterations on every stage.
///
/// Why not the Rosenbrock method (rosenbrock.hpp, docs/performance.md): a
/// Rosenbrock step is exact for the Jacobian frozen at y_n and explicit for the rest. The stiff
/// directions of this model (shear, extension, rotary inertia) turn with the segments in the
/// coordinates (x, p, ẋ, ṗ), so the part of the stiff response that has turned over the step is
/// integrated explicitly, and the step map is unstable beyond a few ms. Here every stage equation
///   Z_i = h Σ_{j<i} a_ij F(y_n + Z_j) + h γ F(y_n + Z_i)
/// is solved by Newton iterations with the residual evaluated at the iterate, so the stage is the
/// implicit method's, whatever Jacobian the iteration matrix uses; the Jacobian only has to make
/// the iteration contract.
///
/// Co-rotation: J(y_J) is kept from where it was evaluated and turned to the stage iterate,
/// Δ = P (I − γhJ(y_J))⁻¹ Pᵀ r with P block-diagonal: per segment the left multiplication by the
/// world rotation w_ν = p_ν p̄_ν,J (on p and ṗ; it keeps body directions and the radial one), per
/// vertex the rotation by the mean of its segments' w (on x and ẋ). The model is equivariant under
/// rigid rotations (up to gravity and the clamp), so this is the Jacobian at the stage up to the
/// change of the relative rotations and strains: the turning of the stiff directions that breaks
/// the Rosenbrock step is followed. Without it (corotate = false) the Newton iteration fails where
/// the Rosenbrock step map is unstable.
///
/// J is re-evaluated when a step's contraction factor exceeds 0.1 (for the next step) and when a
/// stage fails to converge (at the current stage iterate, at most twice per stage, then the step
/// is rejected). The iteration matrix is refactorised only when J or h changes (h is kept when the
/// controller asks for a growth below 20 %).
///
/// Linear algebra: the q-half of the stage equation is linear, z_q = s_q + γh (v_n + z_v), and is
/// kept exact, so the Newton correction is Δ_v = (a² I − a B − A)⁻¹ a r_v, Δ_q = γh Δ_v
/// (a = 1/(γh), bandwidth 10; the Rosenbrock integrator's second-order reduction): a Newton
/// iteration costs one f and one banded solve, O(N). Its stopping norm is the error norm with
/// abs_tol also on v (a velocity iteration error integrates into the positions).
///
/// Error estimate: h Σ (b_i − b̂_i) K_i, filtered by (I − γhJ)⁻¹ (Hairer–Wanner IV.8, Shampine),
/// which keeps the order-3 estimate of the non-stiff components and damps the stiff ones (the raw
/// estimate of an L-stable method is not small on very stiff components). A step is accepted when
/// that estimate passes ErrorNorm and also h |err_v,i| ≤ abs_tol + rel_tol |q_i| for every i:
/// the velocity error turns into a position error over the next step, and velocity_abs_tol alone
/// does not move with the tolerance (docs/quatfd.md, "SDIRK4 and the velocity tolerance").

#include <Eigen/Core>

#include "cosserat/quatfd/implicit_integrator.hpp"

namespace cosserat::quatfd {

/// The Newton statistics of SdirkIntegrator and RadauIntegrator (implicit_integrator.hpp).
using SdirkStats = NewtonStats;

class SdirkIntegrator final : public ImplicitIntegrator {
 public:
  /// Allocates every buffer; Advance() does not allocate.
  /// corotate: turn the iteration matrix with the segments (see the file comment); false only
  /// for the comparison in the benchmarks and tests.
  SdirkIntegrator(const QuatFdModel& model, const IntegratorOptions& options = {},
                  bool corotate = true);

  const char* name() const override { return "sdirk4-banded"; }

  /// One step of size h from y = [q; v] (Newton to convergence, the Jacobian refreshed when the
  /// iteration does not contract), without step-size control: writes y_new and the filtered error
  /// estimate. Returns false when the stage iterations did not converge even with a fresh
  /// Jacobian. Public for the tests (fixed-step order and step-map stability).
  bool Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h, Eigen::Ref<Eigen::VectorXd> y_new,
            Eigen::Ref<Eigen::VectorXd> error);

 private:
  enum class StageResult { kConverged, kSlow, kDiverged };
  void BeginAdvance(bool continuing) override;
  Trial TryStep(double h) override;
  double Rejected(double h, const Trial& trial) override;
  double Accepted(double h, double err) override;
  /// M_ = a² I − a B − A for a = 1/(γh).
  bool FactorizeMatrices(double h) override;
  /// The velocity half of the Newton correction: rv ← (turned) a M⁻¹ rv.
  void SolveVelocity(Eigen::Ref<Eigen::VectorXd> rv);
  /// Predictor of stage i's derivative (into guess_): the known one nearest in time.
  void Predict(int i);
  /// Newton iterations for stage i: z_ starts at the predictor; on kConverged z_ is the stage
  /// increment and k_[i] its derivative F(y_n + Z_i).
  StageResult SolveStage(int i, const Eigen::Ref<const Eigen::VectorXd>& y, double h);
  /// max_i h |err_v,i| / (abs_tol + rel_tol max(|q_i|, |q_new,i|)) for the current step (y_,
  /// y_new_, err_): the position error the step's velocity error makes over one step of size h.
  double IntegratedVelocityError(double h) const;

  bool have_k_guess_ = false;  ///< k_[4] holds F at the start of the next step (predictor)
  Eigen::VectorXd z_, dz_, s_, tmp_;
  Eigen::VectorXd k_[5], k0_, guess_;
};

}  // namespace cosserat::quatfd
