#pragma once
/// \file
/// A drill string's rotary table driven by a motor with inertia, instead of at a prescribed
/// speed: J φ̈ = T_m(φ̇) + m₃(0), φ the table's angle about the clamp's axis (base body z), J the
/// table's and motor's rotary inertia, T_m the motor's torque, falling linearly from `torque`
/// at rest to zero at `no_load_speed` (a DC motor; none: constant torque), and m₃(0) the
/// string's torque on the table (its internal moment at s = 0 about the axis). The parameters;
/// RotaryTableDrive (rotary_table_drive.hpp) steps the table with the string.

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

}  // namespace cosserat
