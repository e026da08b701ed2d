#pragma once
/// \file
/// The load interface every solver asks, in both formulations. A load is one class: it says what
/// force it puts on each piece of the rod and what wrench it puts on the tip. The solvers never
/// name a load; they sum what `TotalDistributedForce_W` and `TotalTipWrench` (total_load.hpp)
/// report for the loads of a problem.

#include "cosserat/lie/types.hpp"

namespace cosserat {

/// Frame in which a load is given. kWorld: a dead load, fixed in space. kBody: a follower load,
/// fixed in the section's body frame and turning with it.
enum class LoadFrame { kWorld, kBody };

/// The piece of rod a distributed load acts on: `length` metres around s with `mass` kilograms.
/// A solver that wants the load per unit length asks for length 1 m with mass ρA; one that lumps
/// the load on a vertex asks for the vertex's dual length and lumped mass.
struct LoadSite {
  double s = 0.0;       ///< arc length, m
  double length = 1.0;  ///< m
  double mass = 0.0;    ///< kg on that length
};

/// A wrench [m; n] split by the frame it is fixed in: a dead part in the world frame and a
/// follower part in the body frame of the section it acts on (N·m; N, or per metre).
struct SplitWrench {
  Vec6 dead_W = Vec6::Zero();
  Vec6 follower_B = Vec6::Zero();
};

/// A load that does not depend on the rod's pose or motion. Loads that do (drag, added mass,
/// contact) extend this interface with the state they read and their Jacobian.
class Load {
 public:
  virtual ~Load() = default;
  /// Dead force on the site, world frame, N (N/m for a site of unit length). Zero for point loads.
  virtual Vec3 DistributedForce_W(const LoadSite& site) const {
    (void)site;
    return Vec3::Zero();
  }
  /// Wrench on the tip section, moment about the tip centroid (N·m; N), on a rigid tip body of
  /// mass tip_mass (kg; 0 without one). Zero for distributed loads that have no point part.
  virtual SplitWrench TipWrench(double tip_mass) const {
    (void)tip_mass;
    return {};
  }
};

}  // namespace cosserat
