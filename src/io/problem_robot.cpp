#include "problem_robot.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosserat/robots/eversion_robot.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "problem_chambers.hpp"
#include "problem_rod.hpp"
#include "read_enum.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;

/// The kinds a file may name (RobotKind::kNone is the absence of a "robot").
const std::vector<std::string> kRobotKinds = {"tendon", "jamming", "eversion", "pneumatic"};
const std::vector<std::string> kRoutes = {"parallel", "converging", "helical"};

/// Where tendon guides may sit: within "disk_radius" if given, else within the section's
/// outline (SectionOutline); no check when the file says neither.
Outline GuidesOf(const ObjectReader& robot, const json& top) {
  if (!robot.Has("disk_radius")) return SectionOutline(top);
  Outline out;
  out.radius = ReadNumber(robot, "disk_radius", PositiveNumber(), Presence::kOptional);
  return out;
}

std::optional<Tendon> ParseTendon(const ObjectReader& t, const Outline& guides) {
  const std::optional<std::string> route = ReadChoice(t, "route", kRoutes, Presence::kRequired);
  std::vector<std::string> keys = {"name", "route", "anchor"};
  if (route == "parallel") keys.push_back("offset");
  if (route == "converging") keys.insert(keys.end(), {"offset_base", "offset_tip"});
  if (route == "helical") keys.insert(keys.end(), {"radius", "pitch", "phase"});
  t.AllowOnly(keys, route ? "for a \"" + *route + "\" tendon" : "");
  Tendon out;
  out.name = ReadString(t, "name", Presence::kOptional).value_or("");
  out.anchor = ReadNumber(t, "anchor", PositiveNumber(), Presence::kOptional).value_or(0.0);
  if (!route) return std::nullopt;
  // Each offset (a helix: every point of it) must lie within the guides.
  bool ok = true;
  const std::string wider = "; set robot.disk_radius for guide disks wider than the rod)";
  auto inside = [&](const std::string& key, const Vec2& r, bool helix) {
    if (guides.radius && r.norm() > *guides.radius) {
      t.report().Expected(t.PathOf(key),
                          "an offset within the section (|r| <= " + FormatNumber(*guides.radius) +
                              " m" + wider,
                          FormatNumber(r.norm()) + " m from the axis");
      ok = false;
    } else if (const auto& e = guides.half_extent;
               e && (helix ? r.norm() > e->minCoeff()
                           : std::abs(r.x()) > e->x() || std::abs(r.y()) > e->y())) {
      t.report().Expected(t.PathOf(key),
                          (helix ? "a helix within the rectangle (radius <= " +
                                       FormatNumber(e->minCoeff()) + " m"
                                 : "an offset within the rectangle (|x| <= " +
                                       FormatNumber(e->x()) + " m, |y| <= " +
                                       FormatNumber(e->y()) + " m") +
                              wider,
                          helix ? FormatNumber(r.norm()) + " m"
                                : "[" + FormatNumber(r.x()) + ", " + FormatNumber(r.y()) + "]");
      ok = false;
    }
  };
  if (*route == "parallel") {
    const auto r = ReadOffset(t, "offset");
    if (!r) return std::nullopt;
    inside("offset", *r, false);
    out.route = TendonRoute::Parallel(*r);
  } else if (*route == "converging") {
    const auto a = ReadOffset(t, "offset_base"), b = ReadOffset(t, "offset_tip");
    if (!a || !b) return std::nullopt;
    inside("offset_base", *a, false);
    inside("offset_tip", *b, false);
    out.route = TendonRoute::Converging(*a, *b);
  } else {
    const auto radius = ReadNumber(t, "radius", PositiveNumber(), Presence::kRequired);
    const NumberRule nonzero{"a non-zero number (m per turn; > 0 turns anticlockwise about z)",
                             [](double x) { return x != 0.0; }};
    const auto pitch = ReadNumber(t, "pitch", nonzero, Presence::kRequired);
    const auto phase = ReadNumber(t, "phase", AnyFiniteNumber(), Presence::kOptional);
    if (!radius || !pitch) return std::nullopt;
    inside("radius", Vec2(*radius, 0.0), true);
    out.route = TendonRoute::Helical(*radius, *pitch, phase.value_or(0.0));
  }
  if (!ok) return std::nullopt;
  return out;
}

/// A list of at most `max` non-negative numbers into `out`; nullopt-like false when reported.
bool ReadList(const ObjectReader& o, const std::string& key, int max, const NumberRule& rule,
              double* out, int* count) {
  const json* v = o.Find(key);
  if (!v) return false;
  if (!v->is_array() || v->size() > static_cast<size_t>(max)) {
    o.report().Expected(o.PathOf(key), "an array of at most " + std::to_string(max) + " numbers",
                        Describe(*v));
    return false;
  }
  bool ok = true;
  for (size_t i = 0; i < v->size(); ++i) {
    const auto x = CheckNumber((*v)[i], ElementPath(o.PathOf(key), i), rule, o.report());
    if (x)
      out[i] = *x;
    else
      ok = false;
  }
  *count = static_cast<int>(v->size());
  return ok;
}

/// "actuation" / "initial_actuation": tensions or lengths, pressure, chamber and jamming
/// pressures.
void ParseActuation(const ObjectReader& a, int tendons, int chambers, int jamming_segments,
                    Actuation* act,
                    std::optional<std::array<double, Actuation::kMaxTendons>>* lengths) {
  std::vector<std::string> keys = {"tension", "pressure", "chamber_pressure", "jamming_pressure"};
  if (lengths) keys.insert(keys.begin() + 1, "length");
  a.AllowOnly(keys);
  if (a.Has("tension") && lengths && a.Has("length"))
    a.report().Add(a.path(),
                   "give either \"tension\" (force control) or \"length\" "
                   "(displacement control), not both");
  auto check_count = [&](const std::string& key, int count) {
    if (count != tendons)
      a.Reject(key, "one value per tendon (" + std::to_string(tendons) + " in robot.tendons)");
  };
  int count = 0;
  if (a.Has("tension")) {
    const NumberRule pull{"a tension >= 0 (N; a tendon cannot push)",
                          [](double x) { return x >= 0; }};
    if (ReadList(a, "tension", Actuation::kMaxTendons, pull, act->tendon_tension.data(), &count))
      check_count("tension", count);
  }
  if (lengths && a.Has("length")) {
    std::array<double, Actuation::kMaxTendons> l{};
    if (ReadList(a, "length", Actuation::kMaxTendons, PositiveNumber(), l.data(), &count)) {
      check_count("length", count);
      *lengths = l;
    }
  }
  if (const auto p = ReadNumber(a, "pressure", NonNegativeNumber(), Presence::kOptional))
    act->pressure = *p;
  if (a.Has("chamber_pressure")) {
    const NumberRule gauge{"a gauge pressure >= -101325 (Pa; -101325 is a vacuum)",
                           [](double x) { return x >= Actuation::kVacuumGaugePressure; }};
    if (ReadList(a, "chamber_pressure", Actuation::kMaxChambers, gauge,
                 act->chamber_pressure.data(), &count) &&
        count != chambers)
      a.Reject("chamber_pressure",
               "one value per chamber (" + std::to_string(chambers) + " in robot.chambers)");
  }
  // ΔP, the vacuum's depth below the ambient pressure: a gauge reading's magnitude.
  const NumberRule vacuum_depth{
      "a pressure difference >= 0 (Pa: the vacuum's depth below ambient, the magnitude of its "
      "negative gauge reading)",
      [](double x) { return x >= 0; }};
  if (a.Has("jamming_pressure") &&
      ReadList(a, "jamming_pressure", Actuation::kMaxSegments, vacuum_depth,
               act->jamming_pressure.data(), &count) &&
      count != jamming_segments)
    a.Reject("jamming_pressure",
             jamming_segments == 0
                 ? std::string("a rod.stiffness_profile of kind \"jamming\" to act on (it has "
                               "no switchable segments)")
                 : "one value per segment of the jamming profile (" +
                       std::to_string(jamming_segments) + " in rod.stiffness_profile.segments)");
}

/// A pressure acts through the section (an inflated tube, a pressure-dependent modulus, a
/// jamming tube): on a rod whose section ignores it, it silently did nothing (a pneumatic finger
/// written with "pressure" where its chambers' "chamber_pressure" was meant). Reported.
void CheckPressureIsRead(const ObjectReader& a, const RodModel& rod, const Actuation& actuation) {
  if (!a.Has("pressure") || actuation.pressure == 0.0 || !rod.section) return;
  Actuation unpressurised = actuation;
  unpressurised.pressure = 0.0;
  const double s = 0.5 * rod.length;
  if (rod.section->At(s, actuation).stiffness == rod.section->At(s, unpressurised).stiffness)
    a.Reject("pressure",
             "a rod.stiffness_profile that depends on it (\"pressure_modulus\", \"inflated\" or "
             "\"jamming\"; the chambers' pressures are \"chamber_pressure\"), or no pressure");
}

/// The switchable segments of a "jamming" rod.stiffness_profile (0 for any other).
/// Whether the file's rod.stiffness_profile gives a "pressure" (its wrapper holds 0 Pa when not,
/// which the robot's actuation then sets without contradicting it).
bool ProfileStatesPressure(const json& top) {
  const auto rod = top.find("rod");
  if (rod == top.end() || !rod->is_object()) return false;
  const auto profile = rod->find("stiffness_profile");
  return profile != rod->end() && profile->is_object() && profile->contains("pressure");
}

int JammingSegments(const json& top) {
  const auto rod = top.find("rod");
  const json* profile = rod != top.end() && rod->is_object() && rod->contains("stiffness_profile")
                            ? &(*rod)["stiffness_profile"]
                            : nullptr;
  // A kind that is not the string "jamming" (another kind, or not a string: reported at
  // rod.stiffness_profile.kind) has no switchable segments.
  if (!profile || !profile->is_object() || !profile->contains("kind") ||
      (*profile)["kind"] != "jamming")
    return 0;
  const auto segments = profile->find("segments");
  return segments != profile->end() && segments->is_array() ? static_cast<int>(segments->size())
                                                            : 0;
}

/// "tendons": each tendon's route, within the guides, and its anchor within the
/// rod.
void ParseTendons(const ObjectReader& robot, const Outline& guide, Problem* p) {
  p->rod.tendons.clear();
  if (const json* t = robot.Find("tendons")) {
    const std::string path = robot.PathOf("tendons");
    if (!t->is_array() || t->size() > static_cast<size_t>(Actuation::kMaxTendons)) {
      robot.report().Expected(
          path, "an array of at most " + std::to_string(Actuation::kMaxTendons) + " tendons",
          Describe(*t));
    } else {
      for (size_t i = 0; i < t->size(); ++i) {
        const std::string tp = ElementPath(path, i);
        if (!(*t)[i].is_object()) {
          robot.report().Expected(tp, "a tendon object {\"route\", ...}", Describe((*t)[i]));
          continue;
        }
        if (auto tendon = ParseTendon(ObjectReader((*t)[i], tp, &robot.report()), guide)) {
          // A rod reported as wrong has no length here: its anchors are then not judged.
          if (p->rod.length > 0 && tendon->anchor > p->rod.length)
            robot.report().Expected(tp + ".anchor",
                                    "an arc length within the rod (<= rod.length, " +
                                        FormatNumber(p->rod.length) + " m; absent: the tip)",
                                    FormatNumber(tendon->anchor) + " m");
          else
            p->rod.tendons.push_back(*tendon);
        }
      }
    }
  } else if (p->robot.kind == RobotKind::kTendon) {
    robot.report().Missing(robot.PathOf("tendons"), "an array of tendons");
  }
}

/// rod.nodes must hold a node at each chamber end and tendon anchor inside the rod, as at every
/// profile breakpoint.
void CheckNodesHoldChamberEnds(const ObjectReader& robot, const Problem& p) {
  const bool anchors = std::any_of(p.rod.tendons.begin(), p.rod.tendons.end(),
                                   [](const Tendon& t) { return t.anchor > 0.0; });
  if ((p.rod.chambers.empty() && !anchors) || !p.rod.section) return;
  const int needed = 2 + InteriorBreakpoints(p.rod.Breakpoints(), p.rod.length);
  if (p.nodes < needed)
    robot.report().Expected("rod.nodes",
                            "at least " + std::to_string(needed) +
                                " (a node at each end, at every stiffness_profile breakpoint, "
                                "chamber end and tendon anchor inside the rod)",
                            std::to_string(p.nodes));
}

/// "tail_tension" (N, >= 0): an eversion robot's tail pulled back to its base.
void ParseTailTension(const ObjectReader& robot, Problem* p) {
  const auto tail = ReadNumber(robot, "tail_tension", NonNegativeNumber(), Presence::kOptional);
  if (!tail) return;
  p->robot.tail_tension = *tail;
  if (p->robot.kind != RobotKind::kEversion)
    robot.report().Add(robot.PathOf("tail_tension"), "only an \"eversion\" robot has a tail");
}

}  // namespace

std::optional<Vec2> ReadOffset(const ObjectReader& o, const std::string& key) {
  const json* v = o.Find(key);
  if (!v) {
    o.report().Missing(o.PathOf(key), "an array [x, y] of 2 numbers (m, body frame)");
    return std::nullopt;
  }
  if (!v->is_array() || v->size() != 2) {
    o.report().Expected(o.PathOf(key), "an array [x, y] of 2 finite numbers (m, body frame)",
                        Describe(*v));
    return std::nullopt;
  }
  // Each coordinate at its own path: offset[1], not the whole pair.
  const auto x = CheckNumber((*v)[0], ElementPath(o.PathOf(key), 0), AnyFiniteNumber(), o.report());
  const auto y = CheckNumber((*v)[1], ElementPath(o.PathOf(key), 1), AnyFiniteNumber(), o.report());
  if (!x || !y) return std::nullopt;
  return Vec2(*x, *y);
}

Outline SectionOutline(const json& top) {
  Outline out;
  if (!top.contains("rod") || !top["rod"].is_object() || !top["rod"].contains("section"))
    return out;
  const json& s = top["rod"]["section"];
  if (!s.is_object()) return out;
  // Only a size the file got right bounds anything (a wrong one is reported by the section).
  auto number = [&](const char* key) -> std::optional<double> {
    if (s.contains(key) && s[key].is_number() && s[key].get<double>() > 0)
      return s[key].get<double>();
    return std::nullopt;
  };
  if (auto r = number("radius")) out.radius = r;
  if (auto r = number("outer_radius")) out.radius = r;
  if (auto w = number("width"), h = number("height"); w && h) out.half_extent = Vec2(*w, *h) / 2;
  return out;
}

void ParseRobot(const ObjectReader& robot, const json& top, Problem* p) {
  robot.AllowOnly({"kind", "description", "source", "disk_radius", "tendons", "chambers",
                   "actuation", "initial_actuation", "growth", "tail_tension"});
  p->has_robot = true;
  p->robot.kind = ReadEnum<RobotKind>(robot, "kind", Presence::kRequired, kRobotKinds)
                      .value_or(RobotKind::kNone);
  ReadString(robot, "description", Presence::kOptional);
  ReadString(robot, "source", Presence::kOptional);
  const Outline guide = GuidesOf(robot, top);

  // A profile solved at fixed pressures (rod.stiffness_profile) hands them to the robot; its
  // actuation may change the jamming pressures, and repeat (not contradict) the pressure.
  std::optional<double> profile_pressure;  // Pa, when rod.stiffness_profile sets one
  if (const auto* fixed = dynamic_cast<const FixedActuationSection*>(p->rod.section.get())) {
    if (ProfileStatesPressure(top)) profile_pressure = fixed->actuation().pressure;
    p->robot.actuation.pressure = fixed->actuation().pressure;
    p->robot.actuation.jamming_pressure = fixed->actuation().jamming_pressure;
    p->robot.initial_actuation = p->robot.actuation;
    p->rod.section = fixed->inner();
  }

  ParseTendons(robot, guide, p);
  const int chambers = ParseChambers(robot, top, p);
  if (p->robot.kind == RobotKind::kPneumatic && !robot.Has("chambers"))
    robot.report().Missing(robot.PathOf("chambers"), "an array of chambers");
  CheckNodesHoldChamberEnds(robot, *p);
  if (p->robot.kind == RobotKind::kEversion) {
    // (No rod model: the rod's own errors are reported, and its profile is unknown.)
    if (p->rod.section && !dynamic_cast<const InflatedTubeSection*>(p->rod.section.get()))
      robot.Reject("kind",
                   "a robot whose rod.stiffness_profile is of kind \"inflated\" (the "
                   "tube an eversion robot is made of)");
    if (!p->rod.tendons.empty())
      robot.report().Add(robot.PathOf("tendons"), "an eversion robot has no tendons here");
    if (chambers > 0)
      robot.report().Add(robot.PathOf("chambers"), "an eversion robot has no chambers here");
    // The robot grids its body by length (EversionOptions), at least this densely.
    const EversionOptions grid;
    if (p->rod.length > grid.MaxLength())
      robot.report().Add("rod.length",
                         "expected at most " + FormatNumber(grid.MaxLength()) +
                             " m for an eversion robot (its body is gridded at " +
                             FormatNumber(grid.nodes_per_metre) + " nodes per metre, at most " +
                             FormatNumber(EversionOptions::kMaxNodes) + " nodes), got " +
                             FormatNumber(p->rod.length));
  }
  ParseTailTension(robot, p);
  if (const auto g = ReadObject(robot, "growth", Presence::kOptional)) {
    g->AllowOnly({"initial_length", "steps"});
    const bool known = p->rod.section != nullptr;  // else the rod's errors are reported
    const NumberRule shorter{
        "a length > 0 and <= rod.length (" + FormatNumber(p->rod.length) + " m)",
        [&](double x) { return x > 0 && (!known || x <= p->rod.length); }};
    p->robot.growth_initial_length = ReadNumber(*g, "initial_length", shorter, Presence::kRequired);
    p->robot.growth_steps =
        ReadInteger(*g, "steps", 1, 100000, Presence::kOptional).value_or(p->robot.growth_steps);
    if (p->robot.kind != RobotKind::kEversion)
      robot.report().Add(robot.PathOf("growth"), "only an \"eversion\" robot grows");
  }
  // The tendons the file lists, valid or not (a bad one has its own error; counting only the
  // valid ones would add a second, wrong one at every per-tendon list).
  const json* listed = robot.Find("tendons");
  const int tendons = listed && listed->is_array() ? static_cast<int>(listed->size())
                                                   : static_cast<int>(p->rod.tendons.size());
  const int jamming = JammingSegments(top);
  if (const auto a = ReadObject(robot, "actuation", Presence::kOptional)) {
    ParseActuation(*a, tendons, chambers, jamming, &p->robot.actuation, &p->robot.tendon_lengths);
    if (!profile_pressure) CheckPressureIsRead(*a, p->rod, p->robot.actuation);
    // One pressure: the profile's and the actuation's must agree when both are given (the
    // actuation's silently won).
    if (profile_pressure && a->Has("pressure") && p->robot.actuation.pressure != *profile_pressure)
      a->report().Expected(a->PathOf("pressure"),
                           "the pressure rod.stiffness_profile.pressure sets (" +
                               FormatNumber(*profile_pressure) + " Pa), or no pressure here",
                           FormatNumber(p->robot.actuation.pressure) + " Pa");
  }
  if (const auto a = ReadObject(robot, "initial_actuation", Presence::kOptional))
    ParseActuation(*a, tendons, chambers, jamming, &p->robot.initial_actuation, nullptr);
}

}  // namespace cosserat::io::detail

namespace cosserat::io {

ActuationParse ParseActuationObject(const nlohmann::json& object, const Problem& problem,
                                    const std::string& path) {
  detail::ErrorReport report;
  ActuationParse out;
  if (!object.is_object()) {
    report.Expected(path, "an object with the keys of robot.actuation", detail::Describe(object));
  } else {
    const auto* jamming = dynamic_cast<const JammingSection*>(problem.rod.section.get());
    // Left out, the pressures the section reads stay the problem's (its stiffness profile's, as
    // in a file); tensions and chamber pressures are zero, as in a file.
    Actuation a;
    a.pressure = problem.robot.actuation.pressure;
    a.jamming_pressure = problem.robot.actuation.jamming_pressure;
    const detail::ObjectReader reader(object, path, &report);
    detail::ParseActuation(reader, static_cast<int>(problem.rod.tendons.size()),
                           static_cast<int>(problem.rod.chambers.size()),
                           jamming ? static_cast<int>(jamming->segments().size()) : 0, &a,
                           nullptr);
    detail::CheckPressureIsRead(reader, problem.rod, a);
    if (report.empty()) out.actuation = a;
  }
  out.errors = report.TakeLines();
  return out;
}

}  // namespace cosserat::io
