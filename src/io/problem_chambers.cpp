#include "problem_chambers.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "problem_robot.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;

/// The chamber's disc of area A (radius a = sqrt(A/π)) at `offset` must lie within the outline;
/// else reported at `<chamber>.offset`, and false.
bool CheckInside(const ObjectReader& c, const Outline& outline, const Vec2& offset, double area) {
  const double a = std::sqrt(area / M_PI);
  if (outline.radius && offset.norm() + a > *outline.radius) {
    c.report().Expected(c.PathOf("offset"),
                        "a chamber within the section (|offset| + sqrt(area/pi) <= outer radius " +
                            FormatNumber(*outline.radius) + " m)",
                        FormatNumber(offset.norm()) + " + " + FormatNumber(a) + " m");
  } else if (outline.half_extent && (std::abs(offset.x()) + a > outline.half_extent->x() ||
                                     std::abs(offset.y()) + a > outline.half_extent->y())) {
    c.report().Expected(c.PathOf("offset"),
                        "a chamber within the rectangle (|x| + sqrt(area/pi) <= " +
                            FormatNumber(outline.half_extent->x()) + " m, |y| + sqrt(area/pi) <= " +
                            FormatNumber(outline.half_extent->y()) + " m)",
                        "[" + FormatNumber(offset.x()) + ", " + FormatNumber(offset.y()) +
                            "] with sqrt(area/pi) = " + FormatNumber(a) + " m");
  } else {
    return true;
  }
  return false;
}

std::optional<Chamber> ParseChamber(const ObjectReader& c, const Outline& outline, double length) {
  c.AllowOnly({"name", "offset", "area", "from", "to"});
  Chamber out;
  out.name = ReadString(c, "name", Presence::kOptional).value_or("");
  const auto offset = ReadOffset(c, "offset");
  const auto area = ReadNumber(
      c, "area", {"a positive number (m²)", [](double x) { return x > 0; }}, Presence::kRequired);
  const std::string within = "within [0, rod.length] (" + FormatNumber(length) + " m)";
  const NumberRule on_rod{"a number " + within, [&](double x) { return x >= 0 && x <= length; }};
  const auto from = ReadNumber(c, "from", on_rod, Presence::kOptional);
  const auto to = ReadNumber(c, "to", on_rod, Presence::kOptional);
  if (c.Has("from") && !from) return std::nullopt;
  if (c.Has("to") && !to) return std::nullopt;
  out.start = from.value_or(0.0);
  out.end = to.value_or(length);
  if (!std::isfinite(out.end)) return std::nullopt;  // no "to" and no rod length
  if (!(out.start < out.end)) {
    c.report().Expected(c.PathOf(c.Has("to") ? "to" : "from"),
                        "from < to (the chamber runs from s = from to s = to, m)",
                        "from = " + FormatNumber(out.start) + ", to = " + FormatNumber(out.end));
    return std::nullopt;
  }
  if (!offset || !area) return std::nullopt;
  if (!CheckInside(c, outline, *offset, *area)) return std::nullopt;
  out.offset = *offset;
  out.area = *area;
  return out;
}

/// Two chambers whose spans along the rod overlap must not overlap across the section: their
/// discs (radius sqrt(area/π)) must lie apart. Reported at the later one's offset.
void CheckApart(const ObjectReader& robot, const std::string& path,
                const std::vector<Chamber>& chambers, const std::vector<size_t>& index) {
  for (size_t j = 0; j < chambers.size(); ++j)
    for (size_t i = 0; i < j; ++i) {
      const Chamber &a = chambers[i], &b = chambers[j];
      if (!(std::max(a.start, b.start) < std::min(a.end, b.end))) continue;
      const double apart = std::sqrt(a.area / M_PI) + std::sqrt(b.area / M_PI);
      const double distance = (a.offset - b.offset).norm();
      if (distance >= apart) continue;
      robot.report().Expected(ElementPath(path, index[j]) + ".offset",
                              "a chamber apart from " + ElementPath(path, index[i]) +
                                  ", which runs beside it (offsets at least sqrt(area/pi) + "
                                  "sqrt(area/pi) = " + FormatNumber(apart) + " m apart)",
                              FormatNumber(distance) + " m apart");
      return;
    }
}

}  // namespace

int ParseChambers(const ObjectReader& robot, const json& top, Problem* p) {
  p->rod.chambers.clear();
  const json* list = robot.Find("chambers");
  if (!list) return 0;
  const std::string path = robot.PathOf("chambers");
  if (!list->is_array() || list->empty() ||
      list->size() > static_cast<size_t>(Actuation::kMaxChambers)) {
    robot.report().Expected(
        path, "an array of 1 to " + std::to_string(Actuation::kMaxChambers) + " chambers",
        Describe(*list));
    return 0;
  }
  const Outline outline = SectionOutline(top);
  std::vector<size_t> index;  // of each parsed chamber in the list
  for (size_t i = 0; i < list->size(); ++i) {
    const std::string cp = ElementPath(path, i);
    if (!(*list)[i].is_object()) {
      robot.report().Expected(cp, "a chamber object {\"offset\", \"area\", \"from\", \"to\"}",
                              Describe((*list)[i]));
      continue;
    }
    // A rod whose length was reported as wrong has none: the ends are then only checked >= 0.
    const double length = p->rod.length > 0 ? p->rod.length : INFINITY;
    if (auto c = ParseChamber(ObjectReader((*list)[i], cp, &robot.report()), outline, length)) {
      p->rod.chambers.push_back(*c);
      index.push_back(i);
    }
  }
  CheckApart(robot, path, p->rod.chambers, index);
  return static_cast<int>(list->size());
}

}  // namespace cosserat::io::detail
