#include "cosserat/robots/stewart_gough.hpp"

#include <cmath>
#include <string>

namespace cosserat {

Assembly ContinuumStewartGough(const StewartGoughParameters& p) {
  const double a1 = p.alpha, a2 = 2.0 * M_PI / 3.0 - p.alpha;
  const Material steel = Material::FromPoissonRatio(p.youngs_modulus, p.poisson_ratio, p.density);
  Assembly a;
  RigidBody platform;
  platform.name = "platform";
  platform.mass = p.platform_mass;
  platform.pose.p = Vec3(0, 0, p.rod_length);
  a.bodies.push_back(platform);
  for (int i = 0; i < 6; ++i) {
    // Angles of hole i: the base's holes go round by a2, a1, a2, a1, … from −a2/2 (pairs a2
    // apart, a1 between pairs); the platform's by a1, a2, … from −a1/2.
    const double theta_b = (-a2 + ((i + 1) - (i + 1) % 2) * a2 + (i - i % 2) * a1) / 2;
    const double theta_p = (-a1 + ((i + 1) - (i + 1) % 2) * a1 + (i - i % 2) * a2) / 2;
    AssemblyRod r;
    r.name = "rod" + std::to_string(i + 1);
    r.model = RodModel::Uniform(p.rod_length, CrossSection::Circle(p.rod_radius), steel);
    r.nodes = p.nodes;
    r.base.p = p.circle_radius * Vec3(std::cos(theta_b), std::sin(theta_b), 0);
    r.base_joint = BaseJoint::kTorsionFree;
    r.tip_joint = TipJoint::kClamped;
    r.body = 0;
    r.attachment.p = p.circle_radius * Vec3(std::cos(theta_p), std::sin(theta_p), 0);
    a.rods.push_back(r);
  }
  return a;
}

}  // namespace cosserat
