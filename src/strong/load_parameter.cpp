#include "cosserat/strong/load_parameter.hpp"

#include <algorithm>

#include "cosserat/loads/total_load.hpp"

namespace cosserat {

double StaticLoadParameter(const RodModel& rod, const StaticLoads& loads,
                           const Actuation& actuation) {
  const SectionProperties p = rod.section->At(0.0, actuation);
  const double EI = p.max_bending_stiffness();  // N·m²
  const double L = rod.length;
  const Vec3 distributed =
      TotalDistributedForce_W(loads, LoadSite{0.0, 1.0, p.mass(3, 3), p.outer_diameter});
  const SplitWrench tip = TotalTipWrench(loads);
  const double force = tip.dead_W.tail<3>().norm() + tip.follower_B.tail<3>().norm();
  const double moment = tip.dead_W.head<3>().norm() + tip.follower_B.head<3>().norm();
  return std::max({force * L * L / EI, moment * L / EI, distributed.norm() * L * L * L / EI});
}

}  // namespace cosserat
