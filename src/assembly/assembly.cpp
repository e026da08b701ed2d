#include "cosserat/assembly/assembly.hpp"

#include <cmath>
#include <string>

#include <Eigen/LU>

namespace cosserat {

namespace {

bool IsRotation(const Mat3& R) {
  return R.allFinite() && (R.transpose() * R - Mat3::Identity()).norm() < 1e-9 &&
         R.determinant() > 0;
}

}  // namespace

bool Assembly::IsValid(std::string* why) const {
  auto fail = [&](const std::string& msg) {
    if (why) *why = msg;
    return false;
  };
  if (rods.empty()) return fail("rods: an assembly needs at least one rod");
  for (size_t b = 0; b < bodies.size(); ++b) {
    const RigidBody& body = bodies[b];
    const std::string name = "bodies[" + std::to_string(b) + "] (" + body.name + ")";
    if (!(std::isfinite(body.mass) && body.mass >= 0)) return fail(name + ".mass: expected >= 0");
    if (!body.pose.p.allFinite() || !IsRotation(body.pose.R))
      return fail(name + ".pose: expected a finite position and a rotation");
    if (!body.force_W.allFinite() || !body.moment_W.allFinite())
      return fail(name + ".force, .moment: expected finite values");
  }
  std::vector<int> joined(bodies.size(), 0);  // rod ends on each body
  for (size_t i = 0; i < rods.size(); ++i) {
    const AssemblyRod& rod = rods[i];
    const std::string name = "rods[" + std::to_string(i) + "] (" + rod.name + ")";
    std::string model_why;
    if (!rod.model.IsValid(&model_why)) return fail(name + ": " + model_why);
    if (rod.nodes < 2) return fail(name + ".nodes: expected at least 2");
    if (!rod.base.p.allFinite() || !IsRotation(rod.base.R))
      return fail(name + ".base: expected a finite position and a rotation");
    if (rod.base_body >= static_cast<int>(bodies.size()) || rod.base_body < -1)
      return fail(name + ".base_body: names body " + std::to_string(rod.base_body) +
                  ", but there are " + std::to_string(bodies.size()));
    if (rod.base_body >= 0) ++joined[rod.base_body];
    const bool free = rod.tip_joint == TipJoint::kFree;
    if (free != (rod.body < 0))
      return fail(name + ".body: " + (free ? "a free tip joins no body"
                                           : "a joined tip names its body"));
    if (!free && rod.body >= static_cast<int>(bodies.size()))
      return fail(name + ".body: names body " + std::to_string(rod.body) + ", but there are " +
                  std::to_string(bodies.size()));
    if (!free && (!rod.attachment.p.allFinite() || !IsRotation(rod.attachment.R)))
      return fail(name + ".attachment: expected a finite position and a rotation");
    if (rod.base_joint == BaseJoint::kTorsionFree && rod.tip_joint != TipJoint::kClamped)
      return fail(name + ": a torsion-free base needs a clamped tip (else the rod spins freely "
                         "about itself)");
    if (!free) ++joined[rod.body];
  }
  for (size_t b = 0; b < bodies.size(); ++b)
    if (joined[b] == 0)
      return fail("bodies[" + std::to_string(b) + "] (" + bodies[b].name +
                  "): no rod holds it (it would fall freely)");
  return true;
}

}  // namespace cosserat
