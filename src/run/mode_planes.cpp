#include "mode_planes.hpp"

#include <cmath>

namespace cosserat::run::detail {
namespace {

/// The unit normal of the plane that holds the equilibrium, or nothing (see ModePlanes).
std::optional<Vec3> PlaneNormal(const RodState& equilibrium, const Vec3& gravity_W) {
  const std::vector<Vec3>& x = equilibrium.position_W;
  if (x.size() < 3) return std::nullopt;
  const Vec3 chord = x.back() - x.front();
  const double length = chord.norm();
  if (!(length > 0.0)) return std::nullopt;
  const Vec3 along = chord / length;
  Vec3 far = Vec3::Zero();  // the farthest node's offset from the chord, m
  for (const Vec3& p : x) {
    const Vec3 off = (p - x.front()) - (p - x.front()).dot(along) * along;
    if (off.norm() > far.norm()) far = off;
  }
  // A sag below 1e-9 of the chord is round-off: the plane is then the chord's and gravity's,
  // if gravity has a part across the chord.
  Vec3 across = far;
  if (!(far.norm() > 1e-9 * length)) {
    across = gravity_W - gravity_W.dot(along) * along;
    if (gravity_W.isZero(0.0) || !(across.norm() > 1e-9 * gravity_W.norm()))
      return std::nullopt;
  }
  return along.cross(across.normalized()).normalized();
}

}  // namespace

std::vector<std::string> ModePlanes(const RodState& equilibrium, const std::vector<Mode>& modes,
                                    const Vec3& gravity_W) {
  std::vector<std::string> planes;
  const std::optional<Vec3> normal = PlaneNormal(equilibrium, gravity_W);
  if (!normal) return planes;
  const std::vector<Vec3>& x = equilibrium.position_W;
  const Vec3 along = (x.back() - x.front()).normalized();
  const Vec3 in_plane = normal->cross(along);
  for (const Mode& m : modes) {
    if (m.displacement_W.empty()) return {};
    double out = 0.0, in = 0.0;  // m² per unit amplitude
    for (const Vec3& u : m.displacement_W) {
      out += std::pow(u.dot(*normal), 2);
      in += std::pow(u.dot(in_plane), 2);
    }
    planes.push_back(out > in ? "out-of-plane" : "in-plane");
  }
  return planes;
}

}  // namespace cosserat::run::detail
