#include "clamp_alignment_note.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "result_rows.hpp"

namespace cosserat::run::detail {
namespace {

constexpr double kAlignedWithin = 20.0;  ///< degrees between a clamp's tangent and the line

/// "[x, y, z]" to three digits.
std::string Vector(const Vec3& v) {
  std::ostringstream text;
  text.precision(3);
  text << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return text.str();
}

/// The index of the first node at least `distance` (m) from the end `from_tip` or not, along s.
std::size_t NodeFrom(const std::vector<double>& s, double distance, bool from_tip) {
  const double L = s.back();
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::size_t i = from_tip ? s.size() - 1 - k : k;
    if ((from_tip ? L - s[i] : s[i]) >= distance) return i;
  }
  return from_tip ? 0 : s.size() - 1;
}

}  // namespace

std::string ClampAlignmentNote(const io::Problem& problem, const Result& result) {
  // An equilibrium's: statics, or the one the modes are about (a run in time ends elsewhere).
  if (problem.boundary != io::Boundary::kAnchored || !problem.rod.section ||
      problem.analysis == io::Analysis::kDynamics || problem.analysis == io::Analysis::kBuckling ||
      !HoldsEquilibrium(result) || !result.json.contains("nodes"))
    return "";
  const nlohmann::ordered_json& nodes = result.json["nodes"];
  if (!nodes.contains("s") || !nodes.contains("position") || !nodes.contains("force_body") ||
      !nodes.contains("moment_body"))
    return "";
  const std::vector<double> s = nodes["s"].get<std::vector<double>>();
  if (s.size() < 3 || nodes["position"].size() != s.size()) return "";
  auto position = [&](std::size_t i) { return VectorAt(nodes["position"][i]); };
  std::ostringstream log;
  log.precision(3);
  const auto note = [&](bool clamped, const Mat3& R, bool tip, const char* field) {
    if (!clamped) return;
    const std::size_t end = tip ? s.size() - 1 : 0;
    const double T = VectorAt(nodes["force_body"][end]).norm();  // N; NaN for nulls
    const double ei =
        problem.rod.section->At(s[end], problem.robot.actuation).min_bending_stiffness();
    if (!(T > 0.0) || !(ei > 0.0)) return;
    const double layer = std::sqrt(ei / T);  // m
    if (9.0 * layer > 0.25 * s.back()) return;
    // The line's direction over [3, 6] and [6, 9] bending lengths from the end (at least a
    // segment each), pointing along s.
    auto direction = [&](double from, double to) {
      std::size_t a = NodeFrom(s, from * layer, tip), b = NodeFrom(s, to * layer, tip);
      if (a == end) a = tip ? end - 1 : end + 1;
      if (b == a) b = tip ? a - 1 : a + 1;
      const Vec3 d = tip ? Vec3(position(a) - position(b)) : Vec3(position(b) - position(a));
      return d.allFinite() && d.norm() > 0.0 ? Vec3(d.normalized()) : Vec3::Constant(NAN);
    };
    const Vec3 along = direction(3.0, 6.0), beyond = direction(6.0, 9.0);
    // A line that turns by over 10° on that scale (a slack cable's low point near the clamp) has
    // no direction beyond the layer to hold the clamp against.
    if (!along.allFinite() || !beyond.allFinite() || along.dot(beyond) < std::cos(M_PI / 18))
      return;
    const Vec3 tangent = R.col(2);
    const double turn = std::acos(std::clamp(tangent.dot(along), -1.0, 1.0));  // rad
    const double angle = turn * 180.0 / M_PI;
    if (!(angle > kAlignedWithin)) return;
    // A clamp the line turns away from carries the layer's moment, 2 sqrt(EI T) sin(θ/2), or a
    // part of it on a grid coarser than the layer (a quarter at h = 8.5 sqrt(EI/T)); a clamp that
    // follows the line carries round-off (1e-6 of it), though the line may bend on its own within
    // 6 sqrt(EI/T) of it (a slack cable's low point). Under a twentieth, no note.
    const Vec3 m = VectorAt(nodes["moment_body"][end]);
    const double moment = std::hypot(m.x(), m.y());  // N·m; NaN for nulls
    if (!(moment >= 0.05 * 2.0 * std::sqrt(ei * T) * std::sin(0.5 * turn))) return;
    log << "cosserat: note: the clamp at " << (tip ? "the anchor" : "s = 0")
        << " holds the rod's tangent " << Vector(tangent) << " (" << field << "'s third column) "
        << angle << "° from the line's direction beyond its bending layer (sqrt(EI/T) = " << layer
        << " m), " << Vector(along) << ": the rod turns through that within a few sqrt(EI/T) of "
        << "the clamp; for a clamp that follows the line, give " << field
        << " that direction as its third column\n";
  };
  note(problem.anchor.base_clamped, problem.base.R, false, "base.rotation");
  note(problem.anchor.tip_clamped, problem.anchor.rotation, true, "anchor.rotation");
  return log.str();
}

}  // namespace cosserat::run::detail
