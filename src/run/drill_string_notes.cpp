#include "drill_string_notes.hpp"

#include <algorithm>
#include <sstream>

namespace cosserat::run::detail {

std::string DrillStringNotes(const io::Problem& problem) {
  if (problem.analysis != io::Analysis::kDynamics) return "";
  std::ostringstream log;
  log.precision(3);
  const BitFriction& bit = problem.loads.bit;
  // The tip force's push up the hole, along −(the clamp's axis), which the string follows to
  // the bit: a force pulling the bit off the rock presses nothing. A force in the tip's frame is
  // taken in the clamp's, as on a straight string.
  const Vec3 axis = problem.base.R.col(2);
  const Vec3 force = problem.loads.tip_force_frame == LoadFrame::kBody
                         ? Vec3(problem.base.R * problem.loads.tip_force)
                         : problem.loads.tip_force;
  const double up = 0.0 - force.dot(axis);  // N, the component up the hole (no −0)
  // Without gravity (torsion alone) there is no weight for the bit to take off the clamp.
  if (bit.present() && !problem.loads.gravity_W.isZero() && up < 0.5 * bit.weight_on_bit) {
    std::ostringstream given;
    given.precision(3);
    const double across = (force + up * axis).norm();  // N, across the hole
    if (up < 0.0)
      given << -up << " N down the hole here, pulling the bit off the rock";
    else
      given << up << " N up the hole here";
    if (across > 0.0) given << ", and " << across << " N across it";
    log << "cosserat: note: loads.bit_friction.weight_on_bit (" << bit.weight_on_bit
        << " N) sets the bit's friction torque only, not the string's axial load: the hole's "
           "bottom pushes on the bit through loads.tip_force ("
        << given.str()
        << "), and the clamp carries the string's weight less that; give tip_force the weight "
           "on bit, pointing up the hole, for both\n";
  }
  const bool spins = problem.dynamics.base_spin != 0.0 || problem.dynamics.rotary_table.present();
  for (int i = 0; spins && i < problem.loads.contact.count; ++i) {
    if (!(problem.loads.contact.surface[i].friction > 0.0)) continue;
    log << "cosserat: note: environment.contact[" << i << "].friction acts on the centreline's "
        << "velocity only: the string's spin makes no friction torque at the wall (μ r N) and "
           "does not lower the axial drag, so the torque at the clamp leaves the wall's out\n";
    break;
  }
  return log.str();
}

}  // namespace cosserat::run::detail
