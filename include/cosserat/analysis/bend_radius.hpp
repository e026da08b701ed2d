#pragma once
/// \file
/// Minimum bend radius (Suulker et al. 2026): the smallest radius of curvature an eversion robot's
/// body reaches as an actuation load grows, before the first of three limits: the actuation
/// limit (the whole load applied), a kink (the bending moment reaches the wrinkling moment
/// π p r(s)³/2 somewhere; beyond it the tube folds and the elastic model no longer describes the
/// shape), or a solve that fails (loss of stability).
///
/// The kink limit is found by bisection in the load factor to a relative 1e-6, so the radius there
/// is R(s) = EI(s)/M_w(s) for the section that kinks: with Suulker et al.'s bands (α E_eff I(s),
/// and M_w ∝ r(s)³) a band reaches α times the plain tube's radius.

#include <string>

#include "cosserat/loads/static_loads.hpp"
#include "cosserat/robots/eversion_robot.hpp"

namespace cosserat {

struct BendRadiusResult {
  double min_radius = 0.0;   ///< smallest radius of curvature 1/|κ⊥| on the body at the limit, m
  double s = 0.0;            ///< where it occurs (material arc length from the base), m
  double load_factor = 0.0;  ///< λ at the limit (1: the whole actuation load)
  /// "actuation", "kink", "angle", "no_convergence", or "kinked_by_fixed_loads" (the fixed loads
  /// alone kink the tube: its radius is a folded tube's, not a bend radius; not ok())
  std::string limit;
  double kink_ratio = 0.0;   ///< max over s of |m⊥|/M_w(s) at the limit (>= 1: kinked)
  int solves = 0;
  bool ok() const { return limit == "actuation" || limit == "kink" || limit == "angle"; }
};

/// Grows `actuation` (a load pattern: tip force or moment, any frame, or a distributed force) from
/// 0 to 1 in `steps` increments on top of `fixed` (gravity, …) at the robot's current length and
/// pressure, then refines the kink onset if one occurs. The robot ends at the limit state. The
/// fixed loads alone are solved first: where they kink the tube, the limit says so at λ = 0.
BendRadiusResult MinimumBendRadius(EversionRobot& robot, const StaticLoads& fixed,
                                   const StaticLoads& actuation, int steps = 20);

/// The minimum bend radius when the actuation turns the tip by `angle` (rad, in (0, π)) from the
/// base direction: λ is found by regula falsi (Illinois) on the angle between the tip and base
/// tangents to 1e-10 rad, on top of `fixed`. limit "angle" (kink_ratio says whether the tube has
/// kinked on the way: a design comparison, not a limit here) or "no_convergence". This is the
/// comparison where layer jamming matters (Do et al. 2023): at a given moment a section's
/// radius is EI/M whatever the rest of the body does, but a given turn made with stiff (jammed)
/// segments concentrates in the compliant ones. Under a pure tip moment the turn is
/// θ = M ∫ ds/EI, so with a fraction f of the length jammed to α times the tube's EI the compliant
/// radius is (1 − f + f/α) L/θ: between (1 − f) L/θ (rigid jamming) and L/θ (none), reached with
/// 1/(1 − f + f/α) times the moment. Throws invalid_argument "angle: ..." outside (0, π).
BendRadiusResult BendRadiusAtTipAngle(EversionRobot& robot, const StaticLoads& fixed,
                                      const StaticLoads& actuation, double angle);

}  // namespace cosserat
