#pragma once
/// \file
/// External loads on a rod in statics: gravity, a uniform distributed force and a tip wrench.

#include <string>

#include "cosserat/lie/types.hpp"

namespace cosserat {

/// Frame in which a tip load is given. kWorld: a dead load, fixed in space. kBody: a follower
/// load, fixed in the tip's body frame and turning with it.
enum class LoadFrame { kWorld, kBody };

struct StaticLoads {
  Vec3 gravity_W = Vec3::Zero();            ///< acceleration of gravity, world frame, m/s²
  Vec3 distributed_force_W = Vec3::Zero();  ///< force per unit length, world frame, N/m
  Vec3 tip_force = Vec3::Zero();            ///< N, in tip_force_frame
  LoadFrame tip_force_frame = LoadFrame::kWorld;
  Vec3 tip_moment = Vec3::Zero();  ///< N·m, in tip_moment_frame
  LoadFrame tip_moment_frame = LoadFrame::kWorld;

  /// Every load multiplied by lambda (used by load stepping).
  StaticLoads Scaled(double lambda) const;
  /// a + t (b − a), with the frames of b (a and b must use the same frames).
  static StaticLoads Blend(const StaticLoads& a, const StaticLoads& b, double t);

  bool IsValid(std::string* why) const;
};

}  // namespace cosserat
