#include "self_crossing_note.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "result_rows.hpp"

namespace cosserat::run::detail {
namespace {

constexpr std::size_t kMostNodes = 2001;

/// The distance between segments [a0, a1] and [b0, b1] (m): their closest points' parameters,
/// the second from the first and both clamped to the segments (Ericson 2005, 5.1.9).
double SegmentDistance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const Vec3 u = a1 - a0, v = b1 - b0, w = a0 - b0;
  const double a = u.squaredNorm(), e = v.squaredNorm(), b = u.dot(v), c = u.dot(w),
               f = v.dot(w), den = a * e - b * b;
  constexpr double kTiny = 1e-300;  // a segment of no length: its one point
  double s = 0.0, t = 0.0;
  if (a <= kTiny && e <= kTiny) return w.norm();
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else if (e <= kTiny) {
    s = std::clamp(-c / a, 0.0, 1.0);
  } else {
    s = den > kTiny ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0.0) {
      t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
      t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return (w + s * u - t * v).norm();
}

}  // namespace

std::string SelfCrossingNote(const io::Problem& problem, const Result& result) {
  // Only an equilibrium (one the grid under-resolves too): a shot that ran away or stopped
  // short has no shape to judge.
  if (problem.analysis != io::Analysis::kStatics || problem.has_assembly ||
      !HoldsEquilibrium(result) ||
      !problem.rod.section || !result.json.contains("nodes"))
    return "";
  const nlohmann::ordered_json& nodes = result.json["nodes"];
  if (!nodes.contains("s") || !nodes.contains("position")) return "";
  const std::vector<double> s = nodes["s"].get<std::vector<double>>();
  if (s.size() < 4 || s.size() > kMostNodes || nodes["position"].size() != s.size()) return "";
  const std::vector<Vec3> x = Vectors(nodes["position"]);
  for (const Vec3& p : x)
    if (!p.allFinite()) return "";
  double d = 0.0;  // the largest outer diameter along the rod, m
  for (double si : s)
    d = std::max(d, problem.rod.section->At(si, problem.robot.actuation).outer_diameter);
  if (!(d > 0.0)) return "";
  for (std::size_t i = 0; i + 1 < s.size(); ++i)
    for (std::size_t j = i + 2; j + 1 < s.size(); ++j) {
      if (s[j] - s[i + 1] < M_PI * d) continue;  // a loop closing on itself is at least π d
      // Segments whose starts lie further apart than both their lengths and d cannot meet.
      const double reach = (x[i + 1] - x[i]).norm() + (x[j + 1] - x[j]).norm() + d;
      if ((x[j] - x[i]).squaredNorm() > reach * reach) continue;
      if (SegmentDistance(x[i], x[i + 1], x[j], x[j + 1]) >= d) continue;
      std::ostringstream note;
      note.precision(3);
      note << "cosserat: note: the rod passes within its outer diameter (" << d
           << " m) of itself between s = " << s[i] << " and " << s[i + 1] << " m and s = " << s[j]
           << " and " << s[j + 1] << " m: the model has no self-contact, so the shape goes "
           << "through where a real rod would press on itself\n";
      return note.str();
    }
  return "";
}

}  // namespace cosserat::run::detail
