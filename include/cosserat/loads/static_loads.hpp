#pragma once
/// \file
/// The loads of a problem by value: gravity, a uniform distributed force, a tip wrench and the
/// fluid around the rod. A plain aggregate, so a controller sets it every step without
/// allocating. Solvers evaluate it
/// only through total_load.hpp, which applies each as its Load class (gravity.hpp,
/// distributed_force.hpp, tip_loads.hpp).

#include <string>

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/bit_friction.hpp"
#include "cosserat/loads/contact.hpp"
#include "cosserat/loads/fluid.hpp"
#include "cosserat/loads/load.hpp"

namespace cosserat {

struct StaticLoads {
  Vec3 gravity_W = Vec3::Zero();            ///< acceleration of gravity, world frame, m/s²
  Vec3 distributed_force_W = Vec3::Zero();  ///< force per unit length, world frame, N/m
  Vec3 tip_force = Vec3::Zero();            ///< N, in tip_force_frame
  LoadFrame tip_force_frame = LoadFrame::kWorld;
  Vec3 tip_moment = Vec3::Zero();  ///< N·m, in tip_moment_frame
  LoadFrame tip_moment_frame = LoadFrame::kWorld;
  Fluid fluid;  ///< buoyancy, drag and added mass (fluid.hpp); none by default
  ContactSurfaces contact;  ///< rigid surfaces (contact.hpp); none by default; never scaled
  /// A drill bit's friction torque about the tip's axis (bit_friction.hpp; dynamics of the SE(3)
  /// stepper); none by default; never scaled.
  BitFriction bit;

  /// Every load multiplied by lambda (used by load stepping): the fluid's flow by √λ, so that
  /// its drag scales by λ; buoyancy scales with gravity.
  StaticLoads Scaled(double lambda) const;
  /// a + t (b − a), with the frames and the fluid of b, its flow velocity blended.
  static StaticLoads Blend(const StaticLoads& a, const StaticLoads& b, double t);

  /// Same values and frames.
  bool operator==(const StaticLoads& other) const;
  bool operator!=(const StaticLoads& other) const { return !(*this == other); }
  /// The tip loads of a and b are given in the same frames (so Blend(a, b, t) is defined).
  static bool SameFrames(const StaticLoads& a, const StaticLoads& b) {
    return a.tip_force_frame == b.tip_force_frame && a.tip_moment_frame == b.tip_moment_frame;
  }

  bool IsValid(std::string* why) const;
};

}  // namespace cosserat
