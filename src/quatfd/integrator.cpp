#include "cosserat/quatfd/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cosserat::quatfd {

bool IntegratorOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(rel_tol > 0 && std::isfinite(rel_tol))) return fail("rel_tol: expected a positive number");
  if (!(abs_tol > 0 && std::isfinite(abs_tol))) return fail("abs_tol: expected a positive number");
  if (!(velocity_abs_tol > 0 && std::isfinite(velocity_abs_tol)))
    return fail("velocity_abs_tol: expected a positive number");
  if (!(initial_dt > 0 && std::isfinite(initial_dt)))
    return fail("initial_dt: expected a positive number");
  if (!(max_dt >= 0 && std::isfinite(max_dt))) return fail("max_dt: expected a number >= 0");
  if (!(min_dt > 0 && std::isfinite(min_dt))) return fail("min_dt: expected a positive number");
  if (max_steps < 1) return fail("max_steps: expected at least 1");
  return true;
}

const char* ToString(IntegratorStatus status) {
  switch (status) {
    case IntegratorStatus::kOk:
      return "ok";
    case IntegratorStatus::kStepSizeUnderflow:
      return "step_size_underflow";
    case IntegratorStatus::kMaxSteps:
      return "max_steps";
    case IntegratorStatus::kNotRun:
      break;
  }
  return "not_run";
}

void AcceptStep(const QuatFdModel& model, const IntegratorOptions& options, double h, bool last,
                double t_end, double* t, Eigen::Ref<Eigen::VectorXd> y, IntegratorStats* stats) {
  ++stats->steps;
  stats->last_dt = h;
  *t = last ? t_end : *t + h;  // the last step lands on t_end exactly
  if (options.project) {
    const Eigen::Index n = model.size();
    stats->max_drift_before_projection =
        std::max(stats->max_drift_before_projection, model.Project(y.head(n), y.tail(n)));
  }
}

AdaptiveIntegrator::AdaptiveIntegrator(const QuatFdModel& model, const IntegratorOptions& options)
    : model_(model), options_(options), n_(model.size()), dt_(options.initial_dt) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("IntegratorOptions: " + why);
  for (Eigen::VectorXd* v : {&y_, &y_new_, &err_}) v->resize(2 * n_);
  y_.setConstant(std::numeric_limits<double>::quiet_NaN());  // no state yet (Advance compares)
}

IntegratorStatus AdaptiveIntegrator::Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                                             Eigen::Ref<Eigen::VectorXd> v) {
  const int n = n_;
  const bool continuing = y_.head(n) == q && y_.tail(n) == v;
  y_.head(n) = q;
  y_.tail(n) = v;
  step_start_ = *t;
  model_.set_time(*t);
  BeginAdvance(continuing);
  IntegratorStatus status = IntegratorStatus::kOk;
  long attempts = 0;
  while (*t < t_end) {
    if (++attempts > options_.max_steps) {
      status = IntegratorStatus::kMaxSteps;
      break;
    }
    if (options_.max_dt > 0) dt_ = std::min(dt_, options_.max_dt);
    // Land exactly on t_end; a last step within 1e-12 of it is stretched to it.
    const bool last = *t + dt_ * (1 + 1e-12) >= t_end;
    const double h = last ? t_end - *t : dt_;
    Trial trial = TryStep(h);
    if (trial.ok && (!std::isfinite(trial.err) || !y_new_.allFinite())) trial.err = 1e10;
    if (!trial.ok || trial.err > 1.0) {
      ++stats_.rejected;
      dt_ = Rejected(h, trial);
      last_rejected_ = true;
      if (dt_ < options_.min_dt) {
        status = IntegratorStatus::kStepSizeUnderflow;
        break;
      }
      continue;
    }
    y_.swap(y_new_);
    AcceptStep(model_, options_, h, last, t_end, t, y_, &stats_);
    step_start_ = *t;
    model_.set_time(*t);
    const double next = Accepted(h, trial.err);
    if (!last || next < dt_) dt_ = next;
    last_rejected_ = false;
    if (options_.after_step) {
      try {
        options_.after_step(*t);
      } catch (...) {  // q, v and *t agree when it throws
        q = y_.head(n);
        v = y_.tail(n);
        throw;
      }
    }
  }
  q = y_.head(n);
  v = y_.tail(n);
  return status;
}

}  // namespace cosserat::quatfd
