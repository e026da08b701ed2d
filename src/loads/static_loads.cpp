#include "cosserat/loads/static_loads.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cosserat {

StaticLoads StaticLoads::Scaled(double lambda) const {
  StaticLoads out = *this;
  out.gravity_W *= lambda;
  out.distributed_force_W *= lambda;
  out.tip_force *= lambda;
  out.tip_moment *= lambda;
  out.fluid.velocity_W *= std::sqrt(std::max(lambda, 0.0));
  return out;
}

StaticLoads StaticLoads::Blend(const StaticLoads& a, const StaticLoads& b, double t) {
  StaticLoads out = b;
  out.gravity_W = a.gravity_W + t * (b.gravity_W - a.gravity_W);
  out.distributed_force_W =
      a.distributed_force_W + t * (b.distributed_force_W - a.distributed_force_W);
  out.tip_force = a.tip_force + t * (b.tip_force - a.tip_force);
  out.tip_moment = a.tip_moment + t * (b.tip_moment - a.tip_moment);
  out.fluid.velocity_W = a.fluid.velocity_W + t * (b.fluid.velocity_W - a.fluid.velocity_W);
  return out;
}

bool StaticLoads::operator==(const StaticLoads& other) const {
  return gravity_W == other.gravity_W && distributed_force_W == other.distributed_force_W &&
         tip_force == other.tip_force && tip_moment == other.tip_moment &&
         SameFrames(*this, other) && fluid == other.fluid && contact == other.contact &&
         bit == other.bit;
}

bool StaticLoads::IsValid(std::string* why) const {
  // The first component that is not finite, named as a file names it: "tip_force[2]".
  auto finite = [&](const Vec3& v, const char* name) {
    for (int i = 0; i < 3; ++i) {
      if (std::isfinite(v(i))) continue;
      if (why) *why = std::string(name) + "[" + std::to_string(i) + "] must be finite, got " +
                      std::to_string(v(i));
      return false;
    }
    return true;
  };
  return finite(gravity_W, "gravity") && finite(distributed_force_W, "distributed_force") &&
         finite(tip_force, "tip_force") && finite(tip_moment, "tip_moment") &&
         fluid.IsValid(why) && contact.IsValid(why) && bit.IsValid(why);
}

}  // namespace cosserat
