#pragma once
/// \file
/// What the solvers ask of a problem's loads: the dead force per unit length at a section, the
/// wrench on the tip, the potential of the conservative part. Each load of StaticLoads is applied
/// as its own Load class; the classes are final, so these sums inline to the plain arithmetic.

#include "cosserat/loads/added_mass.hpp"
#include "cosserat/loads/buoyancy.hpp"
#include "cosserat/loads/contact.hpp"
#include "cosserat/loads/distributed_force.hpp"
#include "cosserat/loads/fluid_drag.hpp"
#include "cosserat/loads/gravity.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/loads/tip_loads.hpp"

namespace cosserat {

/// Σ dead force of every load on the site, world frame, N (N/m for a site of unit length).
inline Vec3 TotalDistributedForce_W(const StaticLoads& loads, const LoadSite& site) {
  const Vec3 f = Gravity(loads.gravity_W).DistributedForce_W(site) +
                 DistributedForce(loads.distributed_force_W).DistributedForce_W(site);
  if (!loads.fluid.present()) return f;
  return f + Buoyancy(loads.fluid.density, loads.gravity_W).DistributedForce_W(site);
}

/// True when a fluid's drag acts (a load on the motion that is no potential's gradient).
inline bool HasDrag(const StaticLoads& loads) { return FluidDrag(loads.fluid).DependsOnMotion(); }

/// True when some load depends on the section's motion (TotalMotionForce_W is not zero).
inline bool HasMotionLoads(const StaticLoads& loads) {
  return HasDrag(loads) || PenaltyContact(loads.contact).DependsOnMotion();
}

/// Σ force of the loads that depend on the section's motion, world frame, N (N/m for a site of
/// unit length); with J, its derivative.
inline Vec3 TotalMotionForce_W(const StaticLoads& loads, const LoadSite& site,
                               const SectionMotion& motion, MotionJacobian* J) {
  Vec3 f = Vec3::Zero();
  if (J) *J = MotionJacobian{};
  MotionJacobian part;
  auto add = [&](const Load& load) {
    if (!load.DependsOnMotion()) return;
    f += load.MotionForce_W(site, motion, J ? &part : nullptr);
    if (!J) return;
    J->position += part.position;
    J->tangent += part.tangent;
    J->velocity += part.velocity;
  };
  add(FluidDrag(loads.fluid));
  add(PenaltyContact(loads.contact));
  return f;
}

/// Σ added mass on the normal acceleration of the site, kg (kg/m for a site of unit length).
inline double TotalNormalAddedMass(const StaticLoads& loads, const LoadSite& site) {
  if (!loads.fluid.has_added_mass()) return 0.0;
  return AddedMass(loads.fluid.added_mass, loads.fluid.density).NormalAddedMass(site);
}

/// Σ wrench of every load on the tip section and a tip body of mass tip_mass (kg), moment about
/// the tip centroid: dead part in the world frame, follower part in the tip body frame.
inline SplitWrench TotalTipWrench(const StaticLoads& loads, double tip_mass = 0.0) {
  const SplitWrench f = TipForce(loads.tip_force, loads.tip_force_frame).TipWrench(tip_mass);
  const SplitWrench m = TipMoment(loads.tip_moment, loads.tip_moment_frame).TipWrench(tip_mass);
  SplitWrench out;
  out.dead_W = f.dead_W + m.dead_W;
  out.follower_B = f.follower_B + m.follower_B;
  if (tip_mass != 0.0) out.dead_W += Gravity(loads.gravity_W).TipWrench(tip_mass).dead_W;
  return out;
}

/// True when the static loads are the gradient of a potential, the condition for a stability
/// index: no follower tip load and no tip moment (a moment of fixed direction does work only
/// along its axis in 3-D), and no drag. Contact in statics is a penalty on the position alone.
inline bool LoadsAreConservative(const StaticLoads& loads) {
  const SplitWrench tip = TotalTipWrench(loads);
  return tip.follower_B.isZero(0.0) && tip.dead_W.head<3>().isZero(0.0) && !HasDrag(loads);
}

/// The tip wrench in the tip body frame R_WB (N·m; N): Rᵀ dead + follower.
inline Vec6 TipWrenchInBody(const SplitWrench& w, const Mat3& R_WB) {
  Vec6 out;
  out << R_WB.transpose() * w.dead_W.head<3>() + w.follower_B.head<3>(),
      R_WB.transpose() * w.dead_W.tail<3>() + w.follower_B.tail<3>();
  return out;
}

/// Potential energy of the distributed dead loads on the site at p_W, J (J/m for unit length).
inline double TotalDistributedPotential(const StaticLoads& loads, const LoadSite& site,
                                        const Vec3& p_W) {
  return -TotalDistributedForce_W(loads, site).dot(p_W);
}

/// True when the loads change only at the tip between a and b (the distributed loads are equal).
inline bool SameDistributedLoads(const StaticLoads& a, const StaticLoads& b) {
  return a.gravity_W == b.gravity_W && a.distributed_force_W == b.distributed_force_W &&
         a.fluid == b.fluid && a.contact == b.contact;
}

}  // namespace cosserat
