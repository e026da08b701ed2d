#include "clamp_alignment_note.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cosserat::run::detail {
namespace {

constexpr double kAlignedWithin = 20.0;  ///< degrees between a clamp's tangent and the chord

/// "[x, y, z]" to three digits.
std::string Vector(const Vec3& v) {
  std::ostringstream text;
  text.precision(3);
  text << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return text.str();
}

}  // namespace

std::string ClampAlignmentNote(const io::Problem& problem) {
  if (problem.boundary != io::Boundary::kAnchored) return "";
  const Vec3 chord = problem.anchor.position - problem.base.p;  // world, m
  if (!(chord.norm() > 0.0)) return "";
  const Vec3 along = chord.normalized();
  std::ostringstream log;
  log.precision(3);
  const auto note = [&](bool clamped, const Mat3& R, const char* end, const char* field) {
    if (!clamped) return;
    const Vec3 tangent = R.col(2);
    const double angle = std::acos(std::clamp(tangent.dot(along), -1.0, 1.0)) * 180.0 / M_PI;
    if (!(angle > kAlignedWithin)) return;
    log << "cosserat: note: the clamp at " << end << " holds the rod's tangent " << Vector(tangent)
        << " (" << field << "'s third column) " << angle << "° from the chord between the ends, "
        << Vector(along) << ": the rod turns through that in a bending layer at the clamp; for "
        << "a clamp along the chord, give " << field << " the chord as its third column\n";
  };
  note(problem.anchor.base_clamped, problem.base.R, "s = 0", "base.rotation");
  note(problem.anchor.tip_clamped, problem.anchor.rotation, "the anchor", "anchor.rotation");
  return log.str();
}

}  // namespace cosserat::run::detail
