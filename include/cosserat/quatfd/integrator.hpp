#pragma once
/// \file
/// What the time integrators of the quaternion-FD rod share: options, statistics, status and the
/// interface. The state is q, v = q̇ (QuatFdLayout); the ODE is q̇ = v, v̇ = f(q, v).

#include <Eigen/Core>
#include <functional>
#include <string>

#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::quatfd {

struct IntegratorOptions {
  /// Error control per component i of y = [q; v]: |err_i| ≤ atol_i + rel_tol max(|y_i|, |y_new_i|)
  /// with atol_i = abs_tol for q (m, –) and velocity_abs_tol for v (m/s, 1/s). The velocity
  /// tolerance is looser by default: with a tight one the step follows the velocity of the stiff
  /// axial, shear and rotary-inertia vibrations (10³–10⁷ rad/s, micrometre amplitudes) instead
  /// of the motion (about 5× more steps for the rubber rod at rel_tol 1e-6). RadauIntegrator
  /// measures segments by their rotation (rad, against abs_tol + rel_tol) and ω (rad/s, against
  /// velocity_abs_tol + rel_tol |ω|) instead of the quaternion components (radau.hpp,
  /// RadauErrorMeasure).
  double rel_tol = 1e-6;
  double abs_tol = 1e-6;
  double velocity_abs_tol = 1e-3;
  double initial_dt = 1e-4;  ///< first trial step, s
  double max_dt = 0.0;       ///< largest step, s; 0: no limit
  double min_dt = 1e-14;  ///< a step rejected at a size below this ends the run: kStepSizeUnderflow
  long max_steps = 50000000;  ///< accepted + rejected steps per Advance call before kMaxSteps
  /// Normalise the quaternions and make ṗ ⊥ p after every accepted step (the model's Project).
  bool project = true;
  /// Called after every accepted step with its end time (s), when set: a caller's progress or
  /// interrupt check. It may throw to stop the run: q, v and *t are then that step's end.
  std::function<void(double)> after_step;

  bool IsValid(std::string* why) const;
};

enum class IntegratorStatus {
  kNotRun,
  kOk,                 ///< reached the requested end time
  kStepSizeUnderflow,  ///< the step size fell below IntegratorOptions::min_dt (divergence)
  kMaxSteps,           ///< IntegratorOptions::max_steps attempted steps in one Advance call
};

/// "ok", "step_size_underflow", "max_steps", "not_run".
const char* ToString(IntegratorStatus status);

struct IntegratorStats {
  long steps = 0;                 ///< accepted steps
  long rejected = 0;              ///< rejected steps (error too large or a non-finite trial)
  long f_evaluations = 0;         ///< evaluations of f(q, v)
  long jacobian_evaluations = 0;  ///< of ∂f/∂(q, v) (each also gives f, not counted above)
  long factorizations = 0;        ///< banded LU factorisations
  /// Largest | |p| − 1 | seen at the end of a step, before the projection (after it, the
  /// violation is round-off).
  double max_drift_before_projection = 0.0;
  double last_dt = 0.0;  ///< size of the last accepted step, s
};

/// max_i |err_i| / (atol_i + rel_tol max(|y_i|, |y_new_i|)) over y = [q; v] (q has n entries):
/// the step is accepted when this is ≤ 1.
double ErrorNorm(const IntegratorOptions& options, int n,
                 const Eigen::Ref<const Eigen::VectorXd>& y,
                 const Eigen::Ref<const Eigen::VectorXd>& y_new,
                 const Eigen::Ref<const Eigen::VectorXd>& err);

/// The error of the state the projection keeps: vertex positions and velocities as ErrorNorm;
/// per segment the rotation error δθ = 2 Im(p̄ δp)/|p|² (body frame, rad) against abs_tol +
/// rel_tol, and the angular-velocity error δω (the first variation of ω = 2 Im(p̄ ṗ)/|p|², rad/s)
/// against velocity_abs_tol + rel_tol |ω_k| (ω of y_new). The gauge — the radial parts p·δp and
/// p·δṗ, which the projection discards and neither R(p) nor ω sees — is not measured
/// (RadauErrorMeasure::kPhysical, radau.hpp; docs/performance.md).
double RotationErrorNorm(const IntegratorOptions& options, const QuatFdLayout& layout,
                         const Eigen::Ref<const Eigen::VectorXd>& y,
                         const Eigen::Ref<const Eigen::VectorXd>& y_new,
                         const Eigen::Ref<const Eigen::VectorXd>& err);

/// The bookkeeping of an accepted step of size h (the last one of an Advance call when `last`):
/// counts it in stats, advances *t (to t_end exactly on the last step) and, with
/// options.project, projects y = [q; v] onto |p| = 1, ṗ ⊥ p, recording the drift removed.
void AcceptStep(const QuatFdModel& model, const IntegratorOptions& options, double h, bool last,
                double t_end, double* t, Eigen::Ref<Eigen::VectorXd> y, IntegratorStats* stats);

/// y' = [v; f(q, v)] for y = [q; v] (the index-1 form, Lang & Linn 2009, eq. 4) into out, counted
/// in stats: the right-hand side every integrator here evaluates.
inline void FirstOrderRhs(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& y,
                          Eigen::Ref<Eigen::VectorXd> out, IntegratorStats* stats) {
  const Eigen::Index n = model.size();
  out.head(n) = y.tail(n);
  model.Acceleration(y.head(n), y.tail(n), out.tail(n));
  ++stats->f_evaluations;
}

/// A time integrator bound to one model. Advance() continues from where the last call stopped
/// (keeping its step size), so a run can be cut into output intervals.
class QuatFdIntegrator {
 public:
  virtual ~QuatFdIntegrator() = default;
  /// Integrates (q, v) from *t to t_end. On kOk, *t = t_end. Otherwise *t and (q, v) are those of
  /// the last accepted step.
  virtual IntegratorStatus Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                                   Eigen::Ref<Eigen::VectorXd> v) = 0;
  virtual const IntegratorStats& stats() const = 0;
  virtual const char* name() const = 0;
};

/// The error-controlled step loop of the Dopri5, Rosenbrock, SDIRK and Radau integrators: the step
/// cap (max_steps), max_dt, the last step landing on t_end, the rejection of a step that failed or
/// whose error norm exceeds 1, the min_dt floor, and an accepted step's bookkeeping (AcceptStep).
/// A method supplies one trial step (TryStep) and its step-size rules after a rejection
/// (Rejected) and after an acceptance (Accepted); a proposal after the clipped last step of an
/// Advance call is kept only when it is smaller than the running size.
class AdaptiveIntegrator : public QuatFdIntegrator {
 public:
  IntegratorStatus Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                           Eigen::Ref<Eigen::VectorXd> v) final;
  const IntegratorStats& stats() const final { return stats_; }
  /// The state [q; v] of the last accepted step: within Advance (from after_step) the step just
  /// taken, which Advance hands back in (q, v) only when it returns.
  const Eigen::VectorXd& state() const { return y_; }

 protected:
  /// One trial step: ok = false when it could not be computed (a singular iteration matrix, or
  /// Newton iterations that failed even with a fresh Jacobian); err its error norm (≤ 1: accepted;
  /// set to 1e10 by Advance when it or y_new_ is not finite).
  struct Trial {
    bool ok;
    double err;
  };

  /// Checks the options (std::invalid_argument "IntegratorOptions: …"), allocates y_, y_new_ and
  /// err_ (y_ NaN: no state yet) and sets the first trial step to options.initial_dt.
  AdaptiveIntegrator(const QuatFdModel& model, const IntegratorOptions& options);

  /// Called by Advance once y_ holds the caller's (q, v); continuing: that state is the one the
  /// previous Advance call ended with.
  virtual void BeginAdvance(bool continuing) { (void)continuing; }
  /// One step of size h from y_: the new state into y_new_ (and the error estimate into err_).
  virtual Trial TryStep(double h) = 0;
  /// The size of the next trial after `trial`, of size h, was rejected (s).
  virtual double Rejected(double h, const Trial& trial) = 0;
  /// The proposed size of the next step after a step of size h with error norm err was accepted;
  /// y_ holds the new state (projected), last_rejected_ still says whether a rejection preceded.
  virtual double Accepted(double h, double err) = 0;

  /// f(q, v) at the stage time step_start_ + c h (the model's clock, for a gusting flow), the
  /// clock put back to step_start_ after.
  void StageAcceleration(double c, double h, const Eigen::Ref<const Eigen::VectorXd>& q,
                         const Eigen::Ref<const Eigen::VectorXd>& v,
                         Eigen::Ref<Eigen::VectorXd> out) const {
    model_.set_time(step_start_ + c * h);
    model_.Acceleration(q, v, out);
    model_.set_time(step_start_);
  }

  /// y' = [v; f(q, v)], counted in stats_.
  void F(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> out) {
    FirstOrderRhs(model_, y, out, &stats_);
  }

  const QuatFdModel& model_;
  IntegratorOptions options_;
  IntegratorStats stats_;
  /// s, the time of y_ (the trial step's start). Advance sets it, and the model's clock, where *t
  /// changes: before BeginAdvance and after each accepted step; stages at t + c h go through
  /// StageAcceleration (QuatFdModel::set_time: a gusting flow).
  double step_start_ = 0.0;
  int n_ = 0;                        ///< size of q (and of v)
  double dt_ = 0;                    ///< size of the next trial step, s
  bool last_rejected_ = false;       ///< the last trial step was rejected
  Eigen::VectorXd y_, y_new_, err_;  ///< [q; v] at *t, a trial step's [q; v] and its error
};

}  // namespace cosserat::quatfd
