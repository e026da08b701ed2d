#include <algorithm>
#include <cmath>
#include <string>

#include "cosserat/quatfd/integrator.hpp"

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

}  // namespace cosserat::quatfd
