#include "cosserat/robots/rotary_table_drive.hpp"

#include <algorithm>
#include <cmath>

#include "cosserat/lie/so3.hpp"

namespace cosserat {

namespace {

// Secant iterations on the table's angle per step, and their stop: the angle's change below
// 1e-12 rad (the string's own solve converges its torque to ~1e-10 of EI/L, whose effect on the
// angle, through the table's stiffness J (1.5/dt)², is far below that).
constexpr int kMaxSecantIterations = 12;
constexpr double kAngleTolerance = 1e-12;
// The second start's offset, rad: large enough that the string's torque changes by far more
// than its solve's tolerance (~GJ/h × 1e-6), small beside any twist (the equation is affine in
// the angle to that order).
constexpr double kSecantOffset = 1e-6;
// The table's equation's residual accepted, relative to its largest term.
constexpr double kEquationTolerance = 1e-6;

}  // namespace

RotaryTableDrive::RotaryTableDrive(const RotaryTable& table, const lie::SE3& base)
    : table_(table), base_(base) {}

StepSummary RotaryTableDrive::Step(Bdf2ShootingStepper* stepper, StepInput* input, double dt) {
  const bool bdf2 = steps_ > 0;
  // The table's speed and acceleration at the step's end for its angle there (BDF2 weights
  // 3/2, −2, 1/2 over dt; BDF1 on the first step).
  auto speed_at = [&](double phi) {
    return bdf2 ? (1.5 * phi - 2.0 * phi_ + 0.5 * phi1_) / dt : (phi - phi_) / dt;
  };
  auto acceleration_at = [&](double w) {
    return bdf2 ? (1.5 * w - 2.0 * w_ + 0.5 * w1_) / dt : (w - w_) / dt;
  };
  const Bdf2ShootingStepper::Snapshot start = stepper->Save();
  StepSummary summary;
  // The table's equation's residual (N·m) after a step of the string with the table at phi.
  auto residual = [&](double phi, bool restore) {
    if (restore) stepper->Restore(start);
    const double w = speed_at(phi);
    input->base_pose.R = base_.R * lie::SO3Exp(Vec3(0, 0, phi));
    input->base_twist_B = Vec6::Zero();
    input->base_twist_B(2) = w;
    summary = stepper->Step(*input);
    const double string_torque = stepper->state().wrench_B.front()(2);
    return table_.inertia * acceleration_at(w) - table_.MotorTorque(w) - string_torque;
  };
  // Two starts: the angle the last speed carries the table to, and a nudge of it.
  double a = phi_ + dt * w_, b = a + kSecantOffset;
  double ra = residual(a, false);
  bool converged = summary.converged();
  double rb = converged ? residual(b, true) : 0.0;
  converged = converged && summary.converged();
  // N·m: the size of the equation's terms at the latest trial, for its acceptance.
  auto term_scale = [&](double phi) {
    const double w = speed_at(phi);
    return std::max({std::abs(table_.inertia * acceleration_at(w)),
                     std::abs(table_.MotorTorque(w)),
                     std::abs(stepper->state().wrench_B.front()(2)), 1e-300});
  };
  double scale = term_scale(b);
  for (int it = 0; it < kMaxSecantIterations && converged; ++it) {
    if (rb == ra) break;
    const double c = b - rb * (b - a) / (rb - ra);
    a = b;
    ra = rb;
    b = c;
    rb = residual(b, true);
    converged = summary.converged();
    scale = term_scale(b);
    if (std::abs(b - a) < kAngleTolerance * (1.0 + std::abs(b))) break;
  }
  // The table's equation must hold to the string's solve (its torque to ~1e-10 of EI/L, far
  // below 1e-6 of the equation's terms), else the step is not taken.
  if (!converged || !(std::abs(rb) <= kEquationTolerance * scale)) {
    if (converged) summary.status = SolveStatus::kMaxIterations;
    stepper->Restore(start);
    return summary;
  }
  const double w = speed_at(b);  // before the history moves on
  phi1_ = phi_;
  w1_ = w_;
  phi_ = b;
  w_ = w;
  ++steps_;
  return summary;
}

}  // namespace cosserat
