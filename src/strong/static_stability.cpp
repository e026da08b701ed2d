// Stability of a cantilever equilibrium found by shooting: the Morse index of the second
// variation of the potential energy, by the Sturm count of MorseIndexOfShot with a free tip.
//
// H is symmetric only for conservative loads. A dead moment in the world frame is not (in 3-D it
// does work only along its axis), which makes H(σ) non-symmetric by ½[m]× in the rotation block
// wherever the rod carries a bending moment. Counting the symmetric part ½(H + Hᵀ) is then no
// criterion: it called a cantilever under a dead tip moment ML/EI = 3 unstable where the full
// spectrum of its linearisation (quaternion-FD modes) is real and positive. Tip moments, like
// follower tip loads (Beck's column loses stability by flutter, which statics cannot see), leave
// the index not defined, −1. (The count still takes ½(H + Hᵀ): for conservative loads, H to
// round-off.)
#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/morse_index.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

int StaticShootingSolver::StabilityIndex(const lie::SE3& base, const StaticLoads& loads,
                                         const Vec6& base_wrench_B) const {
  StateTangent start = StateTangent::Zero();
  start.bottomRows<6>() = Mat6::Identity();  // δW(0) along each unit direction; pose clamped
  RodState record;
  std::vector<StateTangent> nodes;
  ShootTangent(base, loads, base_wrench_B, start, &record, &nodes);
  return StabilityIndexFromShot(loads, record, nodes);
}

// Any 6 independent directions of W(0) will do: H = V U⁻¹ does not depend on the basis
// ((V A)(U A)⁻¹ = V U⁻¹), and sym(UᵀV) changes by a congruence. So the tangent of the solver's own
// Jacobian shot (directions: the scaled unknowns) serves as well as the unit directions.
int StaticShootingSolver::StabilityIndexFromShot(const StaticLoads& loads, const RodState& record,
                                                 const std::vector<StateTangent>& nodes) const {
  // Contact in statics is conservative (no damping or friction at rest), and the tangent shot
  // carries its stiffness.
  if (!LoadsAreConservative(loads)) return -1;
  // An eigenvalue counts as negative below −1e-8 EI/L. A rod symmetric about its axis has, past
  // buckling, a whole circle of equilibria (the shape turned about the load axis, with the section
  // turned back at the clamp): H(L) is exactly singular along it, and the solve tolerance (1e-10
  // in units of EI/L) leaves that eigenvalue at ±1e-10 EI/L. An unstable direction weaker than
  // 1e-8 EI/L is one the load is within about 1e-8 of its critical value: marginal either way.
  const double zero = 1e-8 * scale_(0);
  const RefineSegment refine = [&](int i, int parts, RodState* states,
                                   std::vector<ShotTangent>* tangents) {
    return ShootSegmentRefined(i, parts, loads, record, nodes, states, tangents);
  };
  return MorseIndexOfShot(record, nodes, TipVariations::Identity(6, 6), model_.length, zero,
                          refine);
}

}  // namespace cosserat
