#include "cosserat/constitutive/chamber_law.hpp"

#include <algorithm>

namespace cosserat {

Vec6 ChamberWrench(const std::vector<Chamber>& chambers, double s, const Actuation& actuation) {
  Vec6 w = Vec6::Zero();
  const int count = std::min(static_cast<int>(chambers.size()), Actuation::kMaxChambers);
  for (int j = 0; j < count; ++j) {
    const Chamber& c = chambers[j];
    const double force = actuation.chamber_pressure[j] * c.area;  // N, along e3
    if (force == 0.0 || !c.Covers(s)) continue;
    // r × e3 = [r_y, −r_x, 0] with r = [x, y, 0].
    w(0) += force * c.offset.y();
    w(1) -= force * c.offset.x();
    w(5) += force;
  }
  return w;
}

}  // namespace cosserat
