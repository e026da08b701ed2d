#pragma once
/// \file
/// Whether a dynamic run took the rod into an obstacle's core (loads/obstacle_core.hpp): its
/// centreline beyond a plane or a bore's wall (pressed in by more than its radius), or within
/// half the radius of a sphere's centre or a post's axis. The static solvers refuse such a
/// state; in time a penalty too soft for the motion lets the rod through (a cantilever swung
/// onto a sphere of k = 1e3 N/m² passed through it every cycle, "converged"), and so may a step
/// that jumps a thin obstacle. The run goes on; its log warns at the first time it happened.

#include <string>
#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/contact.hpp"

namespace cosserat::run::detail {

class ObstacleCoreWatch {
 public:
  /// Keeps a copy of the surfaces.
  explicit ObstacleCoreWatch(const ContactSurfaces& surfaces) : surfaces_(surfaces) {}

  /// At the start and after every step at time t (s): the nodes' positions (world, m). The
  /// straight path of each node from the last call's positions counts too.
  void Observe(double t, const std::vector<Vec3>& positions);

  /// "cosserat: warning: ..." naming the surface and the first time; empty when none. With
  /// `fixed_step` (the SE(3) path's dt) it names a smaller step as a fix too.
  std::string Warning(bool fixed_step) const;

 private:
  ContactSurfaces surfaces_;
  std::vector<Vec3> last_;  ///< the last call's positions (world, m)
  int surface_ = -1;        ///< the first surface entered, or −1
  double t_ = 0.0;          ///< s, when
};

}  // namespace cosserat::run::detail
