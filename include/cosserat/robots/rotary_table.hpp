#pragma once
/// \file
/// A drill string's rotary table driven by a motor with inertia, instead of at a prescribed
/// speed: J φ̈ = T_m(φ̇) + m₃(0), φ the table's angle about the clamp's axis (base body z), J the
/// table's and motor's rotary inertia, T_m the motor's torque, falling linearly from `torque`
/// at rest to zero at `no_load_speed` (a DC motor; none: constant torque), and m₃(0) the
/// string's torque on the table (its internal moment at s = 0 about the axis). The table's
/// equation is discretised with the stepper's own BDF2 weights (BDF1 on the first step) and
/// solved together with the string's step: secant iterations on the table's angle at the step's
/// end, each a Step of the string from the same state (Save/Restore).

#include <string>

#include "cosserat/lie/se3.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

struct RotaryTable {
  double inertia = 0.0;        ///< J, kg·m² (> 0)
  double torque = 0.0;         ///< the motor's torque at rest, N·m
  double no_load_speed = 0.0;  ///< rad/s (> 0), where the torque falls to zero; 0: constant
  double MotorTorque(double speed) const {
    return no_load_speed > 0.0 ? torque * (1.0 - speed / no_load_speed) : torque;
  }
  bool present() const { return inertia > 0.0; }
};

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
