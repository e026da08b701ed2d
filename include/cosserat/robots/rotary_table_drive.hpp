#pragma once
/// \file
/// Steps a rotary table driven by a motor with inertia (rotary_table.hpp) together with the
/// string it turns: the table's equation J φ̈ = T_m(φ̇) + m₃(0) is discretised with the stepper's
/// own BDF2 weights (BDF1 on the first step) and solved with the string's step by secant
/// iterations on the table's angle at the step's end, each a Step of the string from the same
/// state (Save/Restore; it allocates, so it is not for the real-time path).

#include "cosserat/lie/se3.hpp"
#include "cosserat/robots/rotary_table.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

class RotaryTableDrive {
 public:
  /// The table at rest at angle 0, turning the clamp `base` (the stepper's base pose at t = 0).
  RotaryTableDrive(const RotaryTable& table, const lie::SE3& base);

  /// One step of the string and the table together: writes the table's pose and spin into
  /// *input (its base_pose and base_twist_B), steps the stepper and returns that step's summary
  /// (not converged when the string's step or the secant iterations fail).
  StepSummary Step(Bdf2ShootingStepper* stepper, StepInput* input, double dt);

  double angle() const { return phi_; }  ///< rad
  double speed() const { return w_; }    ///< rad/s

 private:
  RotaryTable table_;
  lie::SE3 base_;
  double phi_ = 0.0, phi1_ = 0.0;  ///< the angle now and one step back
  double w_ = 0.0, w1_ = 0.0;      ///< the speed now and one step back
  int steps_ = 0;
};

}  // namespace cosserat
