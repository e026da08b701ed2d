#include "problem_profile.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosserat/rod/stiffness_profiles.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;

// --- rod.stiffness_profile ---------------------------------------------------------------------
//
// Either the contract's array of bands, or an object {"kind": ...} (docs/problem-format.md).

using Band = BandedSection::Band;

/// An array at `key` of `parent`, or nullptr (reported when present but not an array, or when
/// required and missing).
const json* FindArray(const ObjectReader& parent, const std::string& key,
                      const std::string& expected, Presence presence) {
  const json* v = parent.Find(key);
  if (!v) {
    if (presence == Presence::kRequired) parent.report().Missing(parent.PathOf(key), expected);
    return nullptr;
  }
  if (!v->is_array()) {
    parent.report().Expected(parent.PathOf(key), expected, Describe(*v));
    return nullptr;
  }
  return v;
}

/// One item of an interval list: [start, end) and the item's own reader for its other keys.
struct Interval {
  double start = 0, end = 0;
  std::size_t index = 0;
};

/// Reads `array` (at `path`) of objects {"start", "end", <extra keys>}: 0 <= start < end <= L.
/// `parse_extra(reader, interval)` reads the other keys and returns false on error. Overlaps are
/// reported at the later item's "start"; `in_order` also requires the list sorted along the rod.
/// `noun` names the items in messages ("band", "segment", ...).
template <typename ParseExtra>
bool ParseIntervals(const json& array, const std::string& path, ErrorReport& report,
                    std::optional<double> length, const std::vector<std::string>& keys,
                    const std::string& noun, bool in_order, ParseExtra parse_extra) {
  std::vector<std::string> allowed{"start", "end"};
  allowed.insert(allowed.end(), keys.begin(), keys.end());
  const std::string item_expected = "a " + noun + " {" + QuotedList(allowed) + "}";
  std::vector<Interval> items;
  bool ok = true;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const std::string at = ElementPath(path, i);
    if (!array[i].is_object()) {
      report.Expected(at, item_expected, Describe(array[i]));
      ok = false;
      continue;
    }
    const ObjectReader b(array[i], at, &report);
    b.AllowOnly(allowed);
    const auto start = ReadNumber(b, "start", NonNegativeNumber(), Presence::kRequired);
    const auto end = ReadNumber(b, "end", PositiveNumber(), Presence::kRequired);
    bool item_ok = start && end;
    if (item_ok && *end <= *start) {
      b.Reject("end", "a number greater than start (" + FormatNumber(*start) + ")");
      item_ok = false;
    }
    if (item_ok && length && *end > *length) {
      b.Reject("end", "a number <= rod.length (" + FormatNumber(*length) + ")");
      item_ok = false;
    }
    Interval interval{start.value_or(0), end.value_or(0), i};
    item_ok = parse_extra(b, interval) && item_ok;
    if (item_ok) items.push_back(interval);
    ok = ok && item_ok;
  }
  if (!ok) return false;
  std::vector<Interval> sorted = items;
  if (!in_order)
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const Interval& a, const Interval& b) { return a.start < b.start; });
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    const Interval &prev = sorted[k - 1], &cur = sorted[k];
    if (cur.start < prev.end) {
      const std::string at = ChildPath(ElementPath(path, cur.index), "start");
      report.Expected(at,
                      "a number >= " + FormatNumber(prev.end) + " (the end of " +
                          ElementPath(path, prev.index) + "; " + noun + "s must not overlap" +
                          (in_order ? " and must be listed in order along the rod)" : ")"),
                      Describe(array[cur.index]["start"]));
      ok = false;
    }
  }
  return ok;
}

std::optional<std::vector<Band>> ParseBands(const json& array, const std::string& path,
                                            ErrorReport& report, std::optional<double> length) {
  std::vector<Band> bands;
  const bool ok = ParseIntervals(array, path, report, length, {"factor"}, "band", false,
                                 [&](const ObjectReader& b, const Interval& in) {
                                   const auto factor = ReadNumber(b, "factor", PositiveNumber(),
                                                                  Presence::kRequired);
                                   if (factor) bands.push_back(Band{in.start, in.end, *factor});
                                   return factor.has_value();
                                 });
  if (!ok) return std::nullopt;
  return bands;
}

/// A modulus law object {"E0", "slope"} or {"table": [[p, E], ...]} at `key`. Absent: the
/// constant `default_E0`. `positive`: E must be > 0 (a body's modulus), else >= 0 (a layer's).
std::optional<ModulusLaw> ParseModulusLaw(const ObjectReader& parent, const std::string& key,
                                          double default_E0, bool positive, Presence presence) {
  const std::string expected = R"(a modulus law {"E0", "slope"} or {"table": [[p, E], ...]})";
  if (!parent.Has(key)) {
    if (presence == Presence::kRequired) parent.report().Missing(parent.PathOf(key), expected);
    return presence == Presence::kRequired
               ? std::nullopt
               : std::optional<ModulusLaw>(ModulusLaw::Constant(default_E0));
  }
  const auto law = ReadObject(parent, key, Presence::kRequired, expected);
  if (!law) return std::nullopt;
  law->AllowOnly({"E0", "slope", "table"});
  const NumberRule modulus_rule = positive ? PositiveNumber() : NonNegativeNumber();
  if (!law->Has("table")) {
    const auto E0 = ReadNumber(*law, "E0", modulus_rule, Presence::kOptional);
    const auto slope = ReadNumber(*law, "slope", NonNegativeNumber(), Presence::kOptional);
    if ((law->Has("E0") && !E0) || (law->Has("slope") && !slope)) return std::nullopt;
    return ModulusLaw::Affine(E0.value_or(default_E0), slope.value_or(0.0));
  }
  if (law->Has("E0") || law->Has("slope")) {
    law->report().Expected(law->path(), R"(either "table" or "E0"/"slope")", "both");
    return std::nullopt;
  }
  const std::string table_path = law->PathOf("table");
  const json* rows = FindArray(*law, "table", "an array of [pressure (Pa), modulus (Pa)] rows",
                               Presence::kRequired);
  if (!rows) return std::nullopt;
  if (rows->empty()) {
    law->report().Expected(table_path, "at least one [pressure, modulus] row", "an empty array");
    return std::nullopt;
  }
  std::vector<double> p, E;
  bool ok = true;
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const json& row = (*rows)[i];
    const std::string at = ElementPath(table_path, i);
    if (!row.is_array() || row.size() != 2) {
      law->report().Expected(at, "a [pressure (Pa), modulus (Pa)] pair", Describe(row));
      ok = false;
      continue;
    }
    const auto pi = CheckNumber(row[0], ElementPath(at, 0), NonNegativeNumber(), law->report());
    const auto Ei = CheckNumber(row[1], ElementPath(at, 1), modulus_rule, law->report());
    if (!pi || !Ei) {
      ok = false;
      continue;
    }
    if (!p.empty() && !(*pi > p.back())) {
      law->report().Expected(ElementPath(at, 0),
                             "a pressure greater than the previous row's (" +
                                 FormatNumber(p.back()) + "; pressures must increase)",
                             Describe(row[0]));
      ok = false;
    } else if (!E.empty() && *Ei < E.back()) {
      law->report().Expected(ElementPath(at, 1),
                             "a modulus >= the previous row's (" + FormatNumber(E.back()) +
                                 "; the modulus may not fall with pressure)",
                             Describe(row[1]));
      ok = false;
    }
    p.push_back(*pi);
    E.push_back(*Ei);
  }
  if (!ok) return std::nullopt;
  return ModulusLaw::Table(LinearTable(std::move(p), std::move(E)));
}

const std::vector<std::string>& ProfileKinds() {
  static const std::vector<std::string> kinds = {"bands", "taper", "pressure_modulus", "jamming",
                                                 "inflated"};
  return kinds;
}

std::vector<std::string> ProfileKeys(const std::optional<std::string>& kind) {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> keys = {
      {"bands", {"bands"}},
      {"taper", {"tip", "table", "bands"}},
      {"pressure_modulus", {"modulus", "pressure", "bands"}},
      {"jamming", {"tube_modulus", "pressure", "layer_I", "layer_modulus", "segments", "bands"}},
      {"inflated", {"wall_thickness", "modulus", "pressure", "constrictions"}},
  };
  std::vector<std::string> out{"kind"};
  for (const auto& [name, k] : keys)
    if (!kind || name == *kind)
      for (const std::string& key : k)
        if (std::find(out.begin(), out.end(), key) == out.end()) out.push_back(key);
  return out;
}

/// "rod.section must be a circle (or annulus)" for `kind`; false (reported) if it is not.
bool RequireShape(const ObjectReader& p, const ProfileBase& base, const std::string& kind,
                  bool allow_annulus) {
  if (!base.section) return true;  // its own error is reported already
  const cosserat::SectionShape shape = base.section->shape;
  if (shape == cosserat::SectionShape::kCircle ||
      (allow_annulus && shape == cosserat::SectionShape::kAnnulus))
    return true;
  const char* names[] = {"circle", "annulus", "rectangle", "explicit"};
  p.report().Expected(p.PathOf("kind"),
                      std::string("a ") +
                          (allow_annulus ? R"("circle" or "annulus")" : R"("circle")") +
                          " rod.section for a " + Quote(kind) + " profile",
                      Quote(names[static_cast<int>(shape)]) + " (rod.section.shape)");
  return false;
}

/// Optional "bands" of an object profile, applied on top of `inner`.
std::optional<ProfilePtr> WithBands(const ObjectReader& p, const ProfileBase& base,
                                    std::optional<ProfilePtr> inner) {
  if (!p.Has("bands")) return inner;
  const json* array =
      FindArray(p, "bands", R"(an array of bands {"start", "end", "factor"})", Presence::kOptional);
  const auto bands =
      array ? ParseBands(*array, p.PathOf("bands"), p.report(), base.length) : std::nullopt;
  if (!bands || !inner) return std::nullopt;
  if (bands->empty() || !*inner) return inner;
  return ProfilePtr(std::make_shared<BandedSection>(*inner, *bands));
}

/// The knots of a taper: s (m) with the outer and inner radii there (m; inner 0 for a circle).
struct TaperKnots {
  std::vector<double> s{0.0}, outer, inner;
};

/// Reads one knot's radii from `row` ("radius", or "outer_radius" and "inner_radius" for an
/// annulus, inner < outer) into knots; false (reported) if they are missing or invalid.
bool ReadTaperRadii(const ObjectReader& row, bool annulus, TaperKnots* knots) {
  const auto ro =
      ReadNumber(row, annulus ? "outer_radius" : "radius", PositiveNumber(), Presence::kRequired);
  std::optional<double> ri = 0.0;
  if (annulus) {
    ri = ReadNumber(row, "inner_radius", NonNegativeNumber(), Presence::kRequired);
    if (ro && ri && *ri >= *ro) {
      row.Reject("inner_radius", "a number smaller than outer_radius (" + FormatNumber(*ro) + ")");
      ri.reset();
    }
  }
  if (!ro || !ri) return false;
  knots->outer.push_back(*ro);
  knots->inner.push_back(*ri);
  return true;
}

/// The rows {"s", <radii>} of a taper "table" (at `path`), s increasing in (0, rod.length], as
/// knots; false if any row is invalid (each is reported).
bool ReadTaperTable(const json& rows, const std::string& path, const ObjectReader& p,
                    const ProfileBase& base, bool annulus,
                    const std::vector<std::string>& radius_keys, TaperKnots* knots) {
  bool ok = true;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string at = ElementPath(path, i);
    if (!rows[i].is_object()) {
      p.report().Expected(at, R"(a row {"s", <radii>})", Describe(rows[i]));
      ok = false;
      continue;
    }
    const ObjectReader row(rows[i], at, &p.report());
    std::vector<std::string> keys{"s"};
    keys.insert(keys.end(), radius_keys.begin(), radius_keys.end());
    row.AllowOnly(keys, "for a tapered " + Quote(annulus ? "annulus" : "circle"));
    const auto si = ReadNumber(row, "s", PositiveNumber(), Presence::kRequired);
    const double s_prev = knots->s.back();
    bool row_ok = si.has_value();
    if (si && !(*si > s_prev)) {
      row.Reject("s", "a number greater than the previous row's s (" + FormatNumber(s_prev) +
                          "; rows run from base to tip, s = 0 is rod.section)");
      row_ok = false;
    } else if (si && base.length && *si > *base.length) {
      row.Reject("s", "a number <= rod.length (" + FormatNumber(*base.length) + ")");
      row_ok = false;
    }
    row_ok = ReadTaperRadii(row, annulus, knots) && row_ok;
    if (row_ok) knots->s.push_back(*si);
    ok = ok && row_ok;
  }
  return ok;
}

/// "taper": rod.section at s = 0, then "tip" (linear to s = L) or "table" rows at s in (0, L].
std::optional<ProfilePtr> ParseTaper(const ObjectReader& p, const ProfileBase& base) {
  const bool shape_ok = RequireShape(p, base, "taper", true);
  const bool annulus = base.section && base.section->shape == cosserat::SectionShape::kAnnulus;
  const std::vector<std::string> radius_keys =
      annulus ? std::vector<std::string>{"outer_radius", "inner_radius"}
              : std::vector<std::string>{"radius"};
  if (p.Has("tip") == p.Has("table")) {
    p.report().Expected(p.path(), R"(exactly one of "tip" and "table" for a "taper" profile)",
                        p.Has("tip") ? "both" : "neither");
    return std::nullopt;
  }
  // Knots: s = 0 from rod.section, then the file's rows.
  TaperKnots knots;
  if (base.section) {
    knots.outer.push_back(base.section->outer_radius);
    knots.inner.push_back(base.section->inner_radius);
  }
  bool ok = shape_ok;
  if (p.Has("tip")) {
    const auto tip = ReadObject(p, "tip", Presence::kRequired, "an object with the tip radii");
    if (!tip) return std::nullopt;
    if (shape_ok)
      tip->AllowOnly(radius_keys, "for a tapered " + Quote(annulus ? "annulus" : "circle"));
    ok = shape_ok && ReadTaperRadii(*tip, annulus, &knots) && ok;
    if (base.length) knots.s.push_back(*base.length);
  } else {
    const std::string path = p.PathOf("table");
    const json* rows =
        FindArray(p, "table", R"(an array of rows {"s", <radii>})", Presence::kRequired);
    if (!rows) return std::nullopt;
    if (rows->empty()) {
      p.report().Expected(path, "at least one row", "an empty array");
      return std::nullopt;
    }
    if (shape_ok) ok = ReadTaperTable(*rows, path, p, base, annulus, radius_keys, &knots) && ok;
  }
  if (!ok || !base.complete()) return std::nullopt;
  LinearTable inner_table = annulus ? LinearTable(knots.s, knots.inner) : LinearTable();
  return ProfilePtr(std::make_shared<TaperedSection>(LinearTable(knots.s, knots.outer),
                                                     std::move(inner_table), *base.material));
}

/// The section and material of a pressure-dependent body: E from the law, ν and ρ from
/// rod.material.
std::optional<ProfilePtr> ParsePressureModulus(const ObjectReader& p, const ProfileBase& base) {
  const auto law = ParseModulusLaw(
      p, "modulus", base.material ? base.material->youngs_modulus : 1.0, true, Presence::kRequired);
  if (!law || !base.complete()) return std::nullopt;
  return ProfilePtr(std::make_shared<PressureModulusSection>(*base.section, *base.material, *law));
}

std::optional<ProfilePtr> ParseJamming(const ObjectReader& p, const ProfileBase& base,
                                       Actuation* state) {
  const auto tube_law =
      ParseModulusLaw(p, "tube_modulus", base.material ? base.material->youngs_modulus : 1.0, true,
                      Presence::kOptional);
  const auto layer_I = ReadNumber(p, "layer_I", PositiveNumber(), Presence::kRequired);
  const auto layer_law = ParseModulusLaw(p, "layer_modulus", 0.0, false, Presence::kRequired);
  const std::string path = p.PathOf("segments");
  const json* array = FindArray(
      p, "segments", R"(an array of segments {"start", "end", "pressure"})", Presence::kRequired);
  if (!array) return std::nullopt;
  if (array->empty() || array->size() > static_cast<std::size_t>(Actuation::kMaxSegments)) {
    p.report().Expected(
        path,
        "1 to " + std::to_string(Actuation::kMaxSegments) + " segments (Actuation::kMaxSegments)",
        Describe(*array));
    return std::nullopt;
  }
  std::vector<JammingSegment> segments;
  const bool ok = ParseIntervals(
      *array, path, p.report(), base.length, {"pressure"}, "segment", true,
      [&](const ObjectReader& seg, const Interval& in) {
        const auto dp = ReadNumber(seg, "pressure", NonNegativeNumber(), Presence::kOptional);
        if (seg.Has("pressure") && !dp) return false;
        state->jamming_pressure[in.index] = dp.value_or(0.0);
        segments.push_back(
            {in.start, in.end, layer_I.value_or(1.0), layer_law.value_or(ModulusLaw())});
        return true;
      });
  if (!ok || !tube_law || !layer_I || !layer_law || !base.complete()) return std::nullopt;
  const auto tube =
      std::make_shared<PressureModulusSection>(*base.section, *base.material, *tube_law);
  return ProfilePtr(std::make_shared<JammingSection>(tube, std::move(segments)));
}

std::optional<ProfilePtr> ParseInflated(const ObjectReader& p, const ProfileBase& base) {
  const bool shape_ok = RequireShape(p, base, "inflated", false);
  const auto t = ReadNumber(p, "wall_thickness", PositiveNumber(), Presence::kRequired);
  const double wall = t.value_or(0.0);
  bool wall_ok = t.has_value();
  if (wall_ok && shape_ok && base.section && wall >= base.section->outer_radius) {
    p.Reject("wall_thickness", "a number smaller than rod.section.radius (" +
                                   FormatNumber(base.section->outer_radius) + ")");
    wall_ok = false;
  }
  const auto law = ParseModulusLaw(
      p, "modulus", base.material ? base.material->youngs_modulus : 1.0, true, Presence::kOptional);
  std::vector<InflatedTubeSection::Constriction> constrictions;
  bool ok = true;
  if (p.Has("constrictions")) {
    const json* array =
        FindArray(p, "constrictions",
                  R"(an array of constrictions {"start", "end", "diameter_ratio", "factor"})",
                  Presence::kOptional);
    const NumberRule ratio{"a number in (0, 1]", [](double r) { return r > 0 && r <= 1; }};
    ok = array && ParseIntervals(*array, p.PathOf("constrictions"), p.report(), base.length,
                                 {"diameter_ratio", "factor"}, "constriction", false,
                                 [&](const ObjectReader& c, const Interval& in) {
                                   const auto d =
                                       ReadNumber(c, "diameter_ratio", ratio, Presence::kRequired);
                                   const auto a = ReadNumber(c, "factor", PositiveNumber(),
                                                             Presence::kRequired);
                                   if (!d || !a) return false;
                                   constrictions.push_back({in.start, in.end, *d, *a});
                                   return true;
                                 });
  }
  if (!ok || !wall_ok || !law || !shape_ok || !base.complete()) return std::nullopt;
  return ProfilePtr(std::make_shared<InflatedTubeSection>(
      base.section->outer_radius, wall, *law, base.material->PoissonRatio(), base.material->density,
      std::move(constrictions), base.material->damping));
}

/// The object form {"kind": ...}. Kinds that read the actuation are wrapped in a
/// FixedActuationSection at the pressures the file states.
std::optional<ProfilePtr> ParseProfileObject(const ObjectReader& p, const ProfileBase& base) {
  const auto kind = ReadChoice(p, "kind", ProfileKinds(), Presence::kRequired);
  if (!kind) {
    p.AllowOnly(ProfileKeys(std::nullopt));
    return std::nullopt;
  }
  p.AllowOnly(ProfileKeys(kind), "for a " + Quote(*kind) + " profile");
  if (*kind == "bands") {
    const json* array = FindArray(p, "bands", R"(an array of bands {"start", "end", "factor"})",
                                  Presence::kRequired);
    if (!array) return std::nullopt;
    const auto bands = ParseBands(*array, p.PathOf("bands"), p.report(), base.length);
    if (!bands || !base.complete()) return std::nullopt;
    ProfilePtr uniform = std::make_shared<UniformSection>(*base.section, *base.material);
    if (bands->empty()) return ProfilePtr();
    return ProfilePtr(std::make_shared<BandedSection>(uniform, *bands));
  }
  if (*kind == "taper") return WithBands(p, base, ParseTaper(p, base));

  Actuation state;
  const auto pressure = ReadNumber(p, "pressure", NonNegativeNumber(), Presence::kOptional);
  bool ok = pressure || !p.Has("pressure");
  state.pressure = pressure.value_or(0.0);
  std::optional<ProfilePtr> inner;
  if (*kind == "pressure_modulus") inner = WithBands(p, base, ParsePressureModulus(p, base));
  if (*kind == "jamming") inner = WithBands(p, base, ParseJamming(p, base, &state));
  if (*kind == "inflated") inner = ParseInflated(p, base);
  if (!ok || !inner || !*inner) return std::nullopt;
  return ProfilePtr(std::make_shared<FixedActuationSection>(*inner, state));
}

}  // namespace

std::optional<ProfilePtr> ParseStiffnessProfile(const ObjectReader& rod, const ProfileBase& base) {
  const json* v = rod.Find("stiffness_profile");
  if (!v) return ProfilePtr();
  const std::string path = rod.PathOf("stiffness_profile");
  if (v->is_object()) return ParseProfileObject(ObjectReader(*v, path, &rod.report()), base);
  if (!v->is_array()) {
    rod.report().Expected(
        path, R"(an array of bands {"start", "end", "factor"} or a profile {"kind": ...})",
        Describe(*v));
    return std::nullopt;
  }
  const auto bands = ParseBands(*v, path, rod.report(), base.length);
  if (!bands || !base.complete()) return std::nullopt;
  if (bands->empty()) return ProfilePtr();
  return ProfilePtr(std::make_shared<BandedSection>(
      std::make_shared<UniformSection>(*base.section, *base.material), *bands));
}

}  // namespace cosserat::io::detail
