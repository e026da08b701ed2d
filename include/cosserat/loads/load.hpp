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
  double s = 0.0;               ///< arc length, m
  double length = 1.0;          ///< m
  double mass = 0.0;            ///< kg on that length
  double outer_diameter = 0.0;  ///< of the section, m: what it displaces in a fluid
};

/// The motion of a section, for loads that depend on it (drag, added mass, contact). World frame.
struct SectionMotion {
  Vec3 position_W = Vec3::Zero();  ///< centreline, m
  Vec3 tangent_W = Vec3::UnitZ();  ///< R_WB e₃, unit: the normal of the section
  Vec3 velocity_W = Vec3::Zero();  ///< centreline velocity, m/s (zero in statics)
};

/// ∂f/∂(position, tangent, velocity) of a force f on a site (world frame; N per m, N per unit,
/// N·s/m).
struct MotionJacobian {
  Mat3 position = Mat3::Zero();
  Mat3 tangent = Mat3::Zero();
  Mat3 velocity = Mat3::Zero();
};

/// A wrench [m; n] split by the frame it is fixed in: a dead part in the world frame and a
/// follower part in the body frame of the section it acts on (N·m; N, or per metre).
struct SplitWrench {
  Vec6 dead_W = Vec6::Zero();
  Vec6 follower_B = Vec6::Zero();
};

/// A load on the rod. Most loads do not depend on the rod's state: a dead distributed force and a
/// tip wrench. Loads that do (fluid drag, contact) say so with DependsOnMotion and give their
/// force at a section's motion with its Jacobian; a fluid's added mass is a mass on the normal
/// acceleration. The solvers add all of these through total_load.hpp.
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
  /// True when MotionForce_W is not zero: the solvers then evaluate it at every stage or vertex.
  virtual bool DependsOnMotion() const { return false; }
  /// Force on the site at the section's motion, world frame, N (N/m for a site of unit length);
  /// with J, also its derivative.
  virtual Vec3 MotionForce_W(const LoadSite& site, const SectionMotion& motion,
                             MotionJacobian* J) const {
    (void)site;
    (void)motion;
    if (J) *J = MotionJacobian{};
    return Vec3::Zero();
  }
  /// Mass that moves with the site's centreline in its accelerations normal to the tangent only
  /// (kg; kg/m for unit length): the added mass of a fluid. The force is −m_a (I − t tᵀ) a.
  virtual double NormalAddedMass(const LoadSite& site) const {
    (void)site;
    return 0.0;
  }
};

}  // namespace cosserat
