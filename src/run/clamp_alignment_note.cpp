#include "clamp_alignment_note.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

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
  if (problem.boundary != io::Boundary::kAnchored || !problem.rod.section ||
      !result.json.contains("nodes"))
    return "";
  const nlohmann::ordered_json& nodes = result.json["nodes"];
  if (!nodes.contains("s") || !nodes.contains("position") || !nodes.contains("force_body"))
    return "";
  const std::vector<double> s = nodes["s"].get<std::vector<double>>();
  if (s.size() < 3 || nodes["position"].size() != s.size()) return "";
  auto position = [&](std::size_t i) {
    const auto& p = nodes["position"][i];
    return p[0].is_number() && p[1].is_number() && p[2].is_number()
               ? Vec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>())
               : Vec3::Constant(NAN);
  };
  std::ostringstream log;
  log.precision(3);
  const auto note = [&](bool clamped, const Mat3& R, bool tip, const char* field) {
    if (!clamped) return;
    const std::size_t end = tip ? s.size() - 1 : 0;
    const auto& f = nodes["force_body"][end];
    if (!f[0].is_number() || !f[1].is_number() || !f[2].is_number()) return;
    const double T = Vec3(f[0].get<double>(), f[1].get<double>(), f[2].get<double>()).norm();
    const double ei =
        problem.rod.section->At(s[end], problem.robot.actuation).min_bending_stiffness();
    if (!(T > 0.0) || !(ei > 0.0)) return;
    const double layer = std::sqrt(ei / T);  // m
    if (6.0 * layer > 0.25 * s.back()) return;
    std::size_t near = NodeFrom(s, 3.0 * layer, tip), far = NodeFrom(s, 6.0 * layer, tip);
    if (near == end) near = tip ? end - 1 : end + 1;
    if (far == near) far = tip ? near - 1 : near + 1;
    const Vec3 line = tip ? (position(near) - position(far)) : (position(far) - position(near));
    if (!line.allFinite() || !(line.norm() > 0.0)) return;
    const Vec3 along = line.normalized(), tangent = R.col(2);
    const double angle = std::acos(std::clamp(tangent.dot(along), -1.0, 1.0)) * 180.0 / M_PI;
    if (!(angle > kAlignedWithin)) return;
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
