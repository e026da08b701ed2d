#include "cosserat/loads/obstacle_core.hpp"

#include <algorithm>

namespace cosserat {
namespace {

using Shape = ContactSurface::Shape;

bool HasCore(const ContactSurface& s) {
  return s.stiffness > 0.0;  // a surface of zero stiffness pushes on nothing: a rod may pass it
}

/// A plane's or a bore's core is its far side: the centreline beyond the surface itself, where
/// the rod presses in by more than its radius.
bool FarSideCore(const ContactSurface& s) {
  return s.shape == Shape::kPlane || (s.shape == Shape::kCylinder && s.inside);
}

bool Beyond(const ContactSurface& s, const Vec3& p) {
  Vec3 normal;
  return s.Distance(p, &normal) < 0.0;
}

/// The core's measure of a point: its vector from the sphere's centre, or from the cylinder's
/// axis (the part normal to the axis), m.
Vec3 FromCore(const ContactSurface& s, const Vec3& p) {
  const Vec3 r = p - s.point_W;
  return s.shape == Shape::kSphere ? r : Vec3(r - s.direction_W * s.direction_W.dot(r));
}

/// The distance from the origin to the segment [a, b] (in FromCore's coordinates, where the
/// core is a ball about the origin: for a cylinder both ends are projected on the normal plane).
double DistanceToOrigin(const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  const double t = dd > 0.0 ? std::clamp(-a.dot(d) / dd, 0.0, 1.0) : 0.0;
  return (a + t * d).norm();
}

bool SegmentReaches(const ContactSurface& s, const Vec3& a, const Vec3& b) {
  // The near side of a plane or a bore is convex: a segment leaves it only where an end does.
  if (FarSideCore(s)) return Beyond(s, a) || Beyond(s, b);
  return DistanceToOrigin(FromCore(s, a), FromCore(s, b)) < 0.5 * s.radius;
}

}  // namespace

bool HasObstacleCore(const ContactSurfaces& surfaces) {
  for (int k = 0; k < surfaces.count; ++k)
    if (HasCore(surfaces.surface[k])) return true;
  return false;
}

bool ReachesObstacleCore(const ContactSurfaces& surfaces, const std::vector<Vec3>& before,
                         const std::vector<Vec3>& after) {
  return ObstacleCoreReached(surfaces, before, after) >= 0;
}

int ObstacleCoreReached(const ContactSurfaces& surfaces, const std::vector<Vec3>& before,
                        const std::vector<Vec3>& after) {
  const bool paths = before.size() == after.size();
  for (int k = 0; k < surfaces.count; ++k) {
    const ContactSurface& s = surfaces.surface[k];
    if (!HasCore(s)) continue;
    for (size_t i = 0; i < after.size(); ++i) {
      // What was in the core already (a start the caller gave, a surface moved onto the rod)
      // is not refused again: only what enters it.
      const bool node_was_clear = !paths || !SegmentReaches(s, before[i], before[i]);
      if (node_was_clear && SegmentReaches(s, paths ? before[i] : after[i], after[i])) return k;
      if (i == 0) continue;
      const bool segment_was_clear = !paths || !SegmentReaches(s, before[i - 1], before[i]);
      if (segment_was_clear && SegmentReaches(s, after[i - 1], after[i])) return k;
    }
  }
  return -1;
}

}  // namespace cosserat
