#pragma once
/// \file
/// Radau IIA of order 5 (3 stages, stage order 3, stiffly accurate, L-stable; Hairer & Wanner,
/// Solving ODEs II, Sections IV.5 and IV.8, their RADAU5) for q̇ = v, v̇ = f(q, v) of the
/// quaternion-FD rod, with simplified Newton iterations on the collocation system
///   Z = h (A ⊗ I) F(y_n + Z),  y_{n+1} = y_n + Z_3.
///
/// Why next to SDIRK4 (sdirk.hpp): SDIRK4 has stage order 1, and the over-damped stiff
/// shear/rotary modes of the damped rods behave like a singular perturbation, where the accuracy
/// of the stiff components follows the stage order (order reduction, Hairer–Wanner IV.15).
///
/// Linear algebra: with W = (T⁻¹ ⊗ I) Z, T⁻¹ A⁻¹ T = diag(γ, [[α, −β], [β, α]]) (computed from
/// the coefficients at start-up), a Newton iteration needs one real system (γ/h I − J) and one
/// complex one ((α + iβ)/h I − J). Both use the second-order reduction of the SDIRK and
/// Rosenbrock integrators: the q-half of the collocation system, Z_q = h (A ⊗ I)(v_n + Z_v), is
/// linear and kept exact, so a correction needs (a² I − a B − A)⁻¹ on the velocity half only,
/// a = γ/h (real banded LU) or (α + iβ)/h (complex banded LU, ComplexBandedMatrix).
/// A Newton iteration costs 3 f, one real and one complex banded solve, O(N).
///
/// Co-rotation: as in SdirkIntegrator, J(y_J) is kept and turned with the segments — per stage,
/// to the stage's current iterate: the residual of stage i is turned back by P_iᵀ, the Kronecker
/// system solved, the correction of stage i turned by P_i (an approximate Newton matrix whose
/// mass part is off by the stages' relative rotation, ~h|ω|). One rotation for all three
/// stages made Newton fail beyond ~4–8 ms on the rubber rod (docs/performance.md).
///
/// Starting values: the collocation polynomial of the last accepted step, extrapolated.
/// Error estimate: Hairer's (I − hγ₀J)⁻¹ [γ₀ h f(y_n) + Σ e_i Z_i] (order 3 in the non-stiff
/// components), re-filtered once through f(y_n + err) after a rejection.
/// Measured as the rotation and ω errors the projection keeps (RadauErrorMeasure::kPhysical,
/// the default) or per component of [q; v] (kComponents, set_error_measure).
/// Newton: the first contraction is recorded but not judged (NewtonControl's grace).
/// Step control: Gustafsson's predictive controller with the Newton-count safety factor of
/// RADAU5. J is refreshed when the Newton contraction of a step exceeds a threshold (evaluated
/// right after the accepted step, its f reused as the next f(y_n)); the LUs are
/// redone when J or h changes (h is held for growth below 20 %). A Newton failure with a stale J
/// refreshes J at y_n and retries; with a fresh J the step is rejected, h halved, and the
/// following steps capped at 0.8 of the failed h (the cap growing 5 % per accepted step).

#include <Eigen/Core>

#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/implicit_integrator.hpp"

namespace cosserat::quatfd {

/// What RadauIntegrator's error estimate is measured in (docs/performance.md, "Radau IIA: what
/// sets the step size").
enum class RadauErrorMeasure {
  /// ErrorNorm on every component of [q; v]: a quaternion's four components against abs_tol,
  /// its rate's four against velocity_abs_tol (each + rel_tol |y_i|). The default until the
  /// steel string showed its flaw: there the gauge p·δṗ sets the step at loose tolerances, so
  /// rel_tol 1e-3 took 16 852 steps (8 459 rejected) against 4 620 at 1e-6.
  kComponents,
  /// RotationErrorNorm (integrator.hpp): the error of the state that survives the projection,
  /// rotations in rad and ω in rad/s, the gauge (p·δp, p·δṗ) not measured. The component measure
  /// holds the tangential quaternion components, δθ/2 and about δω/2, to the tolerances: 2×
  /// looser.
  /// On the steel string it removes the rejections caused by p·δṗ (all 161 error rejections of
  /// (b) at rel_tol 1e-6; at 1e-5 the component measure takes 7 001 steps and 2 251 rejections,
  /// more than at 1e-6, this one 4 706 and 328) at the same or better accuracy against a tight
  /// reference; on the rubber rod (a) it takes ~7 % more steps at 1e-6 for a ~25 % smaller error.
  /// The default: a looser tolerance now means fewer steps on both benchmark rods (steel string
  /// at rel_tol 1e-3 / 1e-4 / 1e-5 / 1e-6: 3 588 / 4 299 / 4 706 / 5 175 steps).
  kPhysical,
};

class RadauIntegrator final : public ImplicitIntegrator {
 public:
  /// Allocates every buffer; Advance() does not allocate.
  RadauIntegrator(const QuatFdModel& model, const IntegratorOptions& options = {},
                  bool corotate = true);

  /// newton_stats().newton_iterations counts iterations of the 3-stage system (3 f each).
  const char* name() const override { return "radau5-banded"; }

  /// One step of size h from y = [q; v] without step-size control (Newton from zero starting
  /// values unless a polynomial of an earlier step is kept): writes y_new and the filtered error
  /// estimate (for which it evaluates f(y) once). Returns false when Newton did not converge even
  /// with a fresh Jacobian. Public for the tests.
  bool Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h, Eigen::Ref<Eigen::VectorXd> y_new,
            Eigen::Ref<Eigen::VectorXd> error);
  /// Newton stopping threshold κ (η‖ΔZ‖ ≤ κ in the error norm); for the fixed-step tests.
  void set_newton_kappa(double kappa) { newton_.set_kappa(kappa); }
  /// Forget the extrapolation polynomial (the next Step starts Newton from Z = 0).
  void ForgetHistory() { have_poly_ = false; }
  /// How the error estimate is measured (default kPhysical); set before Advance.
  void set_error_measure(RadauErrorMeasure measure) { error_measure_ = measure; }
  RadauErrorMeasure error_measure() const { return error_measure_; }

 private:
  enum class NewtonResult { kConverged, kSlow, kDiverged };
  void BeginAdvance(bool continuing) override;
  Trial TryStep(double h) override;
  /// Step with f0_ = f(y) already in place (Advance keeps it for y_).
  bool Attempt(const Eigen::Ref<const Eigen::VectorXd>& y, double h,
               Eigen::Ref<Eigen::VectorXd> y_new, Eigen::Ref<Eigen::VectorXd> error);
  double Rejected(double h, const Trial& trial) override;
  double Accepted(double h, double err) override;
  /// The real (γ/h) and complex ((α + iβ)/h) iteration matrices.
  bool FactorizeMatrices(double h) override;
  /// RADAU5's step-size quotient h/h_new for the error norm err, its safety factor reduced with
  /// the Newton iterations of the last converged step.
  double StepQuotient(double err) const;
  /// Keeps the collocation polynomial of the accepted step of size h (Newton form about 1, c2,
  /// c1) for the next starting values.
  void KeepPolynomial(double h);
  /// Starting values Z_i for a step of size h (the last polynomial, or zero).
  void StartingValues(double h);
  /// Z_q = h (A ⊗ I)(v_n + Z_v): the exact q-half.
  void FillPositions(const Eigen::Ref<const Eigen::VectorXd>& y, double h);
  NewtonResult Newton(const Eigen::Ref<const Eigen::VectorXd>& y, double h);
  /// (γ/h I − J) x = r in place on a full vector (the error filter), co-rotated (slot 3).
  void SolveReal(Eigen::Ref<Eigen::VectorXd> r);
  /// The norm of the estimate err_ of the step y_ → y_new_ (≤ 1: accepted), per error_measure_.
  double ErrorMeasure() const;

  bool jac_at_y_ = false;     ///< J was evaluated at y_ after the last accepted step
  double newton_cap_ = 0.0;  ///< largest next step after a Newton failure (0: none)
  bool have_poly_ = false;
  RadauErrorMeasure error_measure_ = RadauErrorMeasure::kPhysical;
  int last_iterations_ = 0;  ///< Newton iterations of the last converged step
  double h_poly_ = 0;        ///< step of the polynomial in cont_
  // Step-size control within one Advance call: its first step (no polynomial yet), and the size
  // and error norm of the last accepted step (Gustafsson's controller).
  bool first_ = true;
  double h_acc_ = 0.0, err_acc_ = 1e-2;
  ComplexBandedMatrix Mc_;  ///< (α + iβ)²/h² I − (α + iβ)/h B − A; the real one is M_
  Eigen::VectorXd f0_, tmp_;
  Eigen::VectorXd Z_[3], K_[3], dW_[3], cont_[3], dZ_;
};

}  // namespace cosserat::quatfd
