#include "problem_buckling.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "read_enum.hpp"

namespace cosserat::io::detail {

using json = nlohmann::json;

void ParseBuckling(const ObjectReader& o, Problem::Buckling* b) {
  o.AllowOnly({"load", "direction", "max", "tendons"});
  const auto load = ReadEnum<BucklingLoad>(o, "load", Presence::kOptional);
  const bool load_ok = load || !o.Has("load");  // a bad load is reported; no follow-up errors
  b->load = load.value_or(b->load);
  const bool actuation_path =
      b->load == BucklingLoad::kTendonTension || b->load == BucklingLoad::kPressure;
  if (actuation_path && o.Has("direction"))
    o.report().Add(o.PathOf("direction"),
                   "not used by a " + Quote(ToString(b->load)) + " load (leave it out)");
  else if (const auto direction = ReadVec3(o, "direction", Presence::kOptional)) {
    if (direction->stableNorm() > 0)
      b->direction = direction->stableNormalized();  // no overflow for entries near 1e300
    else
      o.report().Expected(o.PathOf("direction"), "a non-zero vector", "[0, 0, 0]");
  }
  b->max = ReadNumber(o, "max", PositiveNumber(), Presence::kRequired).value_or(b->max);
  if (const json* w = o.Find("tendons")) {
    const std::string path = o.PathOf("tendons");
    if (!load_ok) {  // nothing to check the weights against
    } else if (b->load != BucklingLoad::kTendonTension) {
      o.report().Add(path, "only a \"tendon_tension\" load has tendon weights");
    } else if (!w->is_array() || w->empty() ||
               w->size() > static_cast<size_t>(Actuation::kMaxTendons)) {
      o.report().Expected(path,
                          "an array of 1 to " + std::to_string(Actuation::kMaxTendons) +
                              " weights >= 0, one per tendon in robot.tendons",
                          Describe(*w));
    } else {
      const NumberRule weight{"a weight >= 0", [](double x) { return x >= 0; }};
      bool ok = true;
      std::vector<double> weights;
      for (size_t i = 0; i < w->size(); ++i) {
        const auto x = CheckNumber((*w)[i], ElementPath(path, i), weight, o.report());
        ok = ok && x.has_value();
        weights.push_back(x.value_or(0.0));
      }
      if (ok && *std::max_element(weights.begin(), weights.end()) <= 0)
        o.report().Expected(path, "at least one weight > 0", "all zero");
      else if (ok)
        b->tendon_weights = std::move(weights);
    }
  }
}

void CheckBucklingActuation(const ObjectReader& top, const Problem& p) {
  const std::string load_path = "buckling.load";
  if (p.buckling.load == BucklingLoad::kTendonTension) {
    if (!p.has_robot || p.robot.kind != RobotKind::kTendon) {
      top.report().Expected(
          load_path,
          "a load this problem has (\"tendon_tension\" needs a robot of "
          "robot.kind \"tendon\")",
          std::string("\"tendon_tension\" with ") +
              (p.has_robot ? "robot.kind " + Quote(ToString(p.robot.kind)) : "no robot"));
      return;
    }
    const size_t n = p.rod.tendons.size();
    const json& v = top.value();
    if (n == 0 && v["robot"].contains("tendons") && v["robot"]["tendons"].is_array() &&
        v["robot"]["tendons"].empty()) {
      top.report().Expected(load_path, "a load this problem has (\"tendon_tension\" needs tendons)",
                            "\"tendon_tension\" with an empty robot.tendons");
      return;
    }
    if (!p.buckling.tendon_weights.empty() && p.buckling.tendon_weights.size() != n &&
        n > 0)  // n == 0: robot.tendons has its own error
      top.report().Expected("buckling.tendons",
                            "one weight per tendon (" + std::to_string(n) + " in robot.tendons)",
                            std::to_string(p.buckling.tendon_weights.size()) +
                                (p.buckling.tendon_weights.size() == 1 ? " weight" : " weights"));
  } else if (p.buckling.load == BucklingLoad::kPressure) {
    // The section must read the inflation pressure: a "pressure_modulus" or "inflated" profile.
    std::string kind;
    const json& v = top.value();
    if (v.contains("rod") && v["rod"].is_object() && v["rod"].contains("stiffness_profile")) {
      const json& sp = v["rod"]["stiffness_profile"];
      if (sp.is_object() && sp.contains("kind") && sp["kind"].is_string())
        kind = sp["kind"].get<std::string>();
    }
    if (kind != "pressure_modulus" && kind != "inflated")
      top.report().Expected(
          load_path,
          "a load this problem has (\"pressure\" needs a pressure-dependent "
          "section: rod.stiffness_profile of kind \"pressure_modulus\" or "
          "\"inflated\")",
          std::string("\"pressure\" with ") +
              (kind.empty() ? "no such profile" : "a " + Quote(kind) + " profile"));
  }
}

void CheckBucklingLoadActs(const ObjectReader& top, const Problem& p) {
  const Problem::Buckling& b = p.buckling;
  const bool column = p.boundary == Boundary::kPinnedPinned ||
                      p.boundary == Boundary::kClampedClamped ||
                      p.boundary == Boundary::kClampedPinned;
  if (column && b.load == BucklingLoad::kTipForce) {
    const Vec3 axis = p.base.R.col(2);
    if (std::abs(b.direction.dot(axis)) < 1e-6)
      top.report().Expected(
          "buckling.direction",
          "a direction with a part along the column's axis, base.rotation's third column [" +
              FormatNumber(axis.x()) + ", " + FormatNumber(axis.y()) + ", " +
              FormatNumber(axis.z()) + "] (the tip's guide takes a force across it whole)",
          "[" + FormatNumber(b.direction.x()) + ", " + FormatNumber(b.direction.y()) + ", " +
              FormatNumber(b.direction.z()) + "]" +
              (top.value()["buckling"].contains("direction") ? "" : " (the default)"));
  }
  if (b.load == BucklingLoad::kGravity && p.loads.fluid.density == 0.0 && p.rod.section) {
    const int n = std::max(p.nodes, 2);
    double mass = 0.0;
    for (int i = 0; i < n; ++i)
      mass += p.rod.section->At(p.rod.length * i / (n - 1), p.robot.actuation).mass(3, 3);
    if (mass == 0.0)
      top.report().Expected("buckling.load",
                            "a load this problem has (\"gravity\" acts on the rod's mass, or "
                            "through a fluid's buoyancy)",
                            "\"gravity\" on a rod of density 0 with no fluid");
  }
}

}  // namespace cosserat::io::detail
