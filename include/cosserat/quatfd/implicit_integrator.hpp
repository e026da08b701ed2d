#pragma once
/// \file
/// What the Newton-type implicit integrators of the quaternion-FD rod (SdirkIntegrator,
/// RadauIntegrator) share beyond the step loop (AdaptiveIntegrator): the Jacobian kept from where
/// it was evaluated (FrozenJacobian), its refresh, the real iteration matrix a² I − a B − A and
/// the h it was factorised for, the co-rotation of the kept Jacobian to the iterate
/// (corotation.hpp), and the simplified Newton iteration's stopping rule and statistics.
///
/// Jacobian policy: J is evaluated at the start of the first step, and again at the start of the
/// step after one whose Newton iterations contracted by less than kThetaRefresh, or when the
/// iteration matrix cannot be factorised with the kept J (then at y_n). What a method does after
/// a Newton failure is its own (SDIRK: J at the stage iterate; Radau: J at y_n). The iteration
/// matrices are refactorised only when J or h changes.

#include <Eigen/Core>
#include <vector>

#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/corotation.hpp"
#include "cosserat/quatfd/frozen_jacobian.hpp"
#include "cosserat/quatfd/integrator.hpp"

namespace cosserat::quatfd {

/// Newton statistics in addition to IntegratorStats.
struct NewtonStats {
  long newton_iterations = 0;  ///< over all stages (Radau: iterations of the 3-stage system)
  long newton_failures = 0;    ///< iterations that did not contract (J refreshed or h cut)
};

/// The stopping rule of a simplified Newton iteration (Hairer & Wanner, Solving ODEs II, Section
/// IV.8): with θ the observed contraction of the correction norm d and η = θ/(1 − θ), converged
/// when η d ≤ κ; given up when θ ≥ 0.99 or d is not finite (diverged) or when θ^(k_max − 1 − k)
/// d/(1 − θ) > κ (too slow to converge within k_max iterations). The first iteration of a solve
/// uses η of the last converged one, as max(η, 1e-16)^0.8. With first_contraction_grace the
/// contraction of the first two corrections is recorded (max_theta) but not judged: only the
/// later ones decide slow or diverged.
class NewtonControl {
 public:
  enum class Verdict { kContinue, kConverged, kSlow, kDiverged };

  NewtonControl(int max_iterations, double kappa, bool first_contraction_grace = false)
      : max_iterations_(max_iterations), kappa_(kappa), grace_(first_contraction_grace) {}

  int max_iterations() const { return max_iterations_; }
  double kappa() const { return kappa_; }
  void set_kappa(double kappa) { kappa_ = kappa; }
  /// The largest θ since the last BeginStep.
  double max_theta() const { return max_theta_; }

  /// Before the first solve of a step.
  void BeginStep() { max_theta_ = 0.0; }
  /// Before the first iteration of a solve.
  void BeginSolve();
  /// After iteration `iteration` (from 0) of a solve, with the norm d of its correction.
  Verdict Check(int iteration, double d);
  /// Forget the convergence rate (after a new Jacobian).
  void ForgetRate() { eta_memory_ = 1.0; }

  NewtonStats stats;

 private:
  int max_iterations_;
  double kappa_;
  bool grace_;
  double eta_memory_ = 1.0;  ///< η of the last converged solve (Hairer–Wanner's η)
  double eta_ = 1.0;         ///< η of the current solve
  double previous_ = 0.0;    ///< d of the previous iteration
  double max_theta_ = 0.0;
};

/// The base of the Newton-type implicit integrators: AdaptiveIntegrator plus the Jacobian,
/// iteration matrix, co-rotation and Newton state above. A method supplies its factorisation for
/// a step size (FactorizeMatrices), its trial step and its step-size rules.
class ImplicitIntegrator : public AdaptiveIntegrator {
 public:
  const NewtonStats& newton_stats() const { return newton_.stats; }

 protected:
  /// A step whose Newton iterations contracted by less than this (θ above it) refreshes J for
  /// the next step: on the rubber rod a J + LU (~20 µs at N = 10) costs less than the extra
  /// iterations; for Radau 0.03 and 0.3 were measured on the rubber rod: 109 and 122 ms against
  /// 105 ms.
  static constexpr double kThetaRefresh = 0.1;

  /// Allocates every buffer. corotate: turn the kept J with the segments (false only for the
  /// comparisons in the benchmarks and tests); rotation_slots: how many co-rotations the method
  /// keeps (one per iterate it turns J to); max_newton_iterations, kappa: NewtonControl.
  /// first_contraction_grace: NewtonControl's.
  ImplicitIntegrator(const QuatFdModel& model, const IntegratorOptions& options, bool corotate,
                     int rotation_slots, int max_newton_iterations, double kappa,
                     bool first_contraction_grace = false);

  /// Evaluates J at y and marks the factorisations stale.
  void RefreshJacobian(const Eigen::Ref<const Eigen::VectorXd>& y);
  /// Factorises the iteration matrices for the step h unless they are current.
  bool Factorize(double h);
  /// The method's iteration matrices for the step h, factorised and counted in stats_
  /// (FactorizeShifted for the real one).
  virtual bool FactorizeMatrices(double h) = 0;
  /// M_ ← a² I − a B − A from the kept J, factorised (counted).
  bool FactorizeShifted(double a);
  /// Before a step of size h from y: J evaluated if there is none or the last step asked for a
  /// fresh one, the matrices factorised (with a fresh J at y when the kept one fails), the Newton
  /// contraction record cleared. False: no factorisation even with a fresh J.
  bool BeginStep(const Eigen::Ref<const Eigen::VectorXd>& y, double h);
  /// After a converged step: a fresh J for the next step if Newton contracted slowly.
  void EndStep() {
    if (newton_.max_theta() > kThetaRefresh) refresh_next_step_ = true;
  }

  /// Co-rotation `slot` from the state of J to y (a no-op without corotate_).
  void UpdateRotation(int slot, const Eigen::Ref<const Eigen::VectorXd>& y) {
    if (corotate_) corotation_[slot].Update(jac_.q, y.head(n_));
  }
  /// r ← P r (or Pᵀ r) with co-rotation `slot`, on one half (n entries) of the state.
  void RotateHalf(int slot, Eigen::Ref<Eigen::VectorXd> r, bool transpose) const {
    if (corotate_) corotation_[slot].Apply(r, transpose);
  }
  /// (aI − J) x = r in place on a full [q; v] vector with the factorised M_ for the shift a, J
  /// turned by co-rotation `slot`: x = P (aI − J(y_J))⁻¹ Pᵀ r.
  void SolveShifted(double a, int slot, Eigen::Ref<Eigen::VectorXd> r);

  FrozenJacobian jac_;
  BandedMatrix M_;       ///< a² I − a B − A, factorised for factor_h_
  double factor_h_ = 0;  ///< the h of the current factorisation; 0: none
  bool refresh_next_step_ = false;
  bool corotate_ = true;
  NewtonControl newton_;
  /// The tolerances of the Newton stopping norm: options_ with abs_tol also on v (a velocity
  /// iteration error integrates into the positions).
  IntegratorOptions newton_norm_;
  Eigen::VectorXd acc_;  ///< n entries of scratch
  std::vector<CoRotation> corotation_;
};

}  // namespace cosserat::quatfd
