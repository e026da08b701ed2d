#include "problem_environment.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/rod/rest_shape.hpp"

namespace cosserat::io::detail {
namespace {

using nlohmann::json;

// A list of 2 to 16 finite numbers at `key`, written to out[0 … count − 1]; false on error.
bool ReadProfileList(const ObjectReader& o, const std::string& key, double* out, int* count) {
  const std::string expected = "an array of 2 to 16 numbers";
  const json* v = o.Find(key);
  if (!v) {
    o.report().Missing(o.PathOf(key), expected);
    return false;
  }
  if (!v->is_array() || v->size() < 2 || v->size() > FluidFlowProfile::kMaxPoints) {
    o.report().Expected(o.PathOf(key), expected, Describe(*v));
    return false;
  }
  for (std::size_t i = 0; i < v->size(); ++i) {
    const auto x = CheckNumber((*v)[i], o.PathOf(key) + "[" + std::to_string(i) + "]",
                               AnyFiniteNumber(), o.report());
    if (!x) return false;
    out[i] = *x;
  }
  *count = static_cast<int>(v->size());
  return true;
}

// "profile": {"axis", "origin", and either "reference_height" + "exponent" (a power law) or
// "heights" + "factors" (a table)}.
void ParseFlowProfile(const ObjectReader& o, FluidFlowProfile* p) {
  o.AllowOnly({"axis", "origin", "reference_height", "exponent", "heights", "factors"});
  if (const auto axis = ReadVec3(o, "axis", Presence::kOptional)) {
    if (!(axis->stableNorm() > 0)) {
      o.report().Expected(o.PathOf("axis"), "a non-zero vector", "[0, 0, 0]");
      return;
    }
    p->axis_W = axis->stableNormalized();  // [1e300, 0, 1] would overflow normalized()
  }
  p->origin_W = ReadVec3(o, "origin", Presence::kOptional).value_or(Vec3::Zero());
  const bool power = o.Find("exponent") || o.Find("reference_height");
  const bool table = o.Find("heights") || o.Find("factors");
  if (power == table) {
    o.report().Expected(o.PathOf("exponent"),
                        "either \"reference_height\" and \"exponent\" (a power law) or "
                        "\"heights\" and \"factors\" (a table)",
                        power ? "both" : "neither");
    return;
  }
  if (power) {
    p->kind = FluidFlowProfile::Kind::kPowerLaw;
    p->reference_height =
        ReadNumber(o, "reference_height", PositiveNumber(), Presence::kRequired).value_or(1.0);
    p->exponent = ReadNumber(o, "exponent", NonNegativeNumber(), Presence::kRequired).value_or(0.0);
    return;
  }
  p->kind = FluidFlowProfile::Kind::kTable;
  int heights = 0, factors = 0;
  if (!ReadProfileList(o, "heights", p->height.data(), &heights)) return;
  if (!ReadProfileList(o, "factors", p->factor.data(), &factors)) return;
  if (heights != factors) {
    o.report().Expected(o.PathOf("factors"), std::to_string(heights) + " numbers (one per height)",
                        std::to_string(factors));
    return;
  }
  for (int i = 1; i < heights; ++i) {
    if (!(p->height[i] > p->height[i - 1])) {
      o.report().Expected(o.PathOf("heights"), "increasing heights",
                          FormatNumber(p->height[i - 1]) + " then " + FormatNumber(p->height[i]));
      return;
    }
  }
  p->points = heights;
}

void ParseFluid(const ObjectReader& o, Fluid* f, FluidGust* gust) {
  o.AllowOnly({"density", "velocity", "drag_normal", "drag_tangential", "added_mass", "diameter",
               "profile", "gust"});
  if (const auto g = ReadObject(o, "gust", Presence::kOptional)) {
    g->AllowOnly({"amplitude", "period"});
    gust->amplitude =
        ReadNumber(*g, "amplitude", NonNegativeNumber(), Presence::kRequired).value_or(0.0);
    gust->period = ReadNumber(*g, "period", PositiveNumber(), Presence::kRequired).value_or(0.0);
  }
  f->density = ReadNumber(o, "density", PositiveNumber(), Presence::kRequired).value_or(0.0);
  f->velocity_W = ReadVec3(o, "velocity", Presence::kOptional).value_or(Vec3::Zero());
  auto coefficient = [&](const char* key) {
    return ReadNumber(o, key, NonNegativeNumber(), Presence::kOptional).value_or(0.0);
  };
  f->drag_normal = coefficient("drag_normal");
  f->drag_tangential = coefficient("drag_tangential");
  f->added_mass = coefficient("added_mass");
  f->diameter = ReadNumber(o, "diameter", PositiveNumber(), Presence::kOptional).value_or(0.0);
  if (const auto p = ReadObject(o, "profile", Presence::kOptional))
    ParseFlowProfile(*p, &f->profile);
}

// A unit vector at `key` (normalised), or nullopt after reporting a zero or bad one.
std::optional<Vec3> ReadDirection(const ObjectReader& o, const std::string& key) {
  const auto v = ReadVec3(o, key, Presence::kRequired);
  if (!v) return std::nullopt;
  if (!(v->stableNorm() > 0)) {
    o.report().Expected(o.PathOf(key), "a non-zero vector", "[0, 0, 0]");
    return std::nullopt;
  }
  return v->stableNormalized();  // [1e300, 0, 1] would overflow normalized()
}

// One surface: {"shape": "plane", "point", "normal"} | {"shape": "sphere", "center", "radius"} |
// {"shape": "cylinder", "point", "axis", "radius", "side"}, each with "stiffness", "damping",
// "friction", "slip_velocity" and "smoothing".
void ParseSurface(const ObjectReader& o, ContactSurface* s) {
  const auto shape = ReadChoice(o, "shape", {"plane", "sphere", "cylinder"}, Presence::kRequired);
  const std::vector<std::string> common = {"shape",    "stiffness",     "damping",
                                           "friction", "slip_velocity", "smoothing"};
  if (!shape) {  // the keys of every shape: a misspelt "shape" is then named with its fix
    std::vector<std::string> any = common;
    for (const char* key : {"point", "normal", "center", "radius", "axis", "side"})
      any.push_back(key);
    o.AllowOnly(any);
    return;
  }
  auto allow = [&](std::vector<std::string> keys) {
    keys.insert(keys.end(), common.begin(), common.end());
    o.AllowOnly(keys, "for a \"" + *shape + "\" surface");
  };
  if (*shape == "plane") {
    allow({"point", "normal"});
    s->shape = ContactSurface::Shape::kPlane;
    s->point_W = ReadVec3(o, "point", Presence::kOptional).value_or(Vec3::Zero());
    s->direction_W = ReadDirection(o, "normal").value_or(Vec3::UnitZ());
  } else if (*shape == "sphere") {
    allow({"center", "radius"});
    s->shape = ContactSurface::Shape::kSphere;
    s->point_W = ReadVec3(o, "center", Presence::kRequired).value_or(Vec3::Zero());
    s->radius = ReadNumber(o, "radius", PositiveNumber(), Presence::kRequired).value_or(1.0);
  } else {
    allow({"point", "axis", "radius", "side"});
    s->shape = ContactSurface::Shape::kCylinder;
    s->point_W = ReadVec3(o, "point", Presence::kOptional).value_or(Vec3::Zero());
    s->direction_W = ReadDirection(o, "axis").value_or(Vec3::UnitZ());
    s->radius = ReadNumber(o, "radius", PositiveNumber(), Presence::kRequired).value_or(1.0);
    s->inside = ReadChoice(o, "side", {"inside", "outside"}, Presence::kRequired) ==
                std::optional<std::string>("inside");
  }
  s->stiffness = ReadNumber(o, "stiffness", PositiveNumber(), Presence::kRequired).value_or(0.0);
  s->damping = ReadNumber(o, "damping", NonNegativeNumber(), Presence::kOptional).value_or(0.0);
  // Left out: 1e-3 of the rod's outer diameter. An explicit 0 used to mean that too, silently;
  // a sharp contact has no derivative for Newton, so a width must be positive.
  const NumberRule width{"a positive width (m); left out, 1e-3 of the rod's outer diameter",
                         [](double x) { return x > 0; }};
  s->smoothing = ReadNumber(o, "smoothing", width, Presence::kOptional).value_or(0.0);
  s->friction = ReadNumber(o, "friction", NonNegativeNumber(), Presence::kOptional).value_or(0.0);
  s->slip_velocity =
      ReadNumber(o, "slip_velocity", PositiveNumber(), Presence::kOptional).value_or(1e-4);
}

void ParseContact(const ObjectReader& o, ContactSurfaces* contact) {
  const std::string expected = "an array of 1 to 8 surface objects";
  const json* v = o.Find("contact");
  if (!v) return;
  if (!v->is_array() || v->empty() || v->size() > kMaxContactSurfaces) {
    o.report().Expected(o.PathOf("contact"), expected, Describe(*v));
    return;
  }
  contact->count = static_cast<int>(v->size());
  for (std::size_t i = 0; i < v->size(); ++i) {
    const std::string path = o.PathOf("contact") + "[" + std::to_string(i) + "]";
    if (!(*v)[i].is_object()) {
      o.report().Expected(path, "a surface object", Describe((*v)[i]));
      continue;
    }
    ParseSurface(ObjectReader((*v)[i], path, &o.report()), &contact->surface[i]);
  }
}

/// Where a point past surface k lies, in words: a bore holds the rod inside it, so past its wall
/// is outside the bore; past any other surface is inside the obstacle it bounds.
std::string PastSurface(const ContactSurface& c) {
  return c.shape == ContactSurface::Shape::kCylinder && c.inside ? "outside this bore"
                                                                 : "inside this surface";
}

}  // namespace

void ParseEnvironment(const ObjectReader& o, Fluid* fluid, FluidGust* gust,
                      ContactSurfaces* contact) {
  o.AllowOnly({"fluid", "contact"});
  if (const auto f = ReadObject(o, "fluid", Presence::kOptional)) ParseFluid(*f, fluid, gust);
  ParseContact(o, contact);
}

/// The unloaded rod must not start with its centreline past a contact surface (a penetration
/// deeper than its outer radius): the penalty would push it on through, or out with an enormous
/// force. Checked on 201 points of the rest centreline; a shallower start is allowed (the
/// surface pushes it out). A line held at both ends starts from a shape hung between them, not
/// from its rest centreline: there its two held points are checked.
void CheckStartsOutsideSurfaces(const Problem& p, ErrorReport* report) {
  const ContactSurfaces& contact = p.loads.contact;
  if (contact.count == 0) return;
  if (p.boundary == Boundary::kAnchored) {
    for (int k = 0; k < contact.count; ++k) {
      const std::string path = "environment.contact[" + std::to_string(k) + "]";
      Vec3 normal;
      for (const auto& [name, point] :
           {std::pair<const char*, Vec3>{"base.position", p.base.p},
            std::pair<const char*, Vec3>{"anchor.position", p.anchor.position}}) {
        const double distance = contact.surface[k].Distance(point, &normal);
        if (distance < 0.0)
          report->Add(path, "the line is held " + PastSurface(contact.surface[k]) + ": its " +
                                name + " is " + FormatNumber(-distance) + " m past it");
      }
    }
  }
  constexpr int kPoints = 201;
  const std::vector<Vec3> centreline = RestCentreline_W(p.rod, p.base, kPoints);
  // A centreline that ends on the surface is not past it: the rest centreline's round-off (a
  // wall placed at the tip of a 0.6 m rod read 4.4e-16 m past it) is forgiven up to 1e-12 L.
  const double round_off = 1e-12 * p.rod.length;  // m
  for (int k = 0; k < contact.count && p.boundary != Boundary::kAnchored; ++k) {
    double deepest = 0.0, s_deepest = 0.0;  // the most negative distance, m, and where
    double s_first = p.rod.length;         // m, the first point past the surface
    for (int i = 0; i < kPoints; ++i) {
      Vec3 normal;
      double distance = contact.surface[k].Distance(centreline[i], &normal);
      if (distance < 0.0 && distance > -round_off) distance = 0.0;
      const double s = p.rod.length * i / (kPoints - 1);
      if (distance < 0.0) s_first = std::min(s_first, s);
      if (distance < deepest) {
        deepest = distance;
        s_deepest = s;
      }
    }
    // A growing rod is checked at its full length: each growth step lays the new material
    // straight on from the tip, through a surface ahead (a vine grown at a wall came out 0.16 m
    // beyond it, "converged"), which the quasi-static growth cannot turn aside. Said when the
    // part it starts with is clear of the surface.
    const std::string growing =
        p.robot.growth_initial_length && s_first > *p.robot.growth_initial_length
            ? " (a growing rod is checked at its full rod.length: its growth would lay new "
              "material through the surface)"
            : "";
    if (deepest < 0.0)
      report->Add("environment.contact[" + std::to_string(k) + "]",
                  "the rod starts " + PastSurface(contact.surface[k]) +
                      ": at s = " + FormatNumber(s_deepest) +
                      " m its centreline is " + FormatNumber(-deepest) + " m past it" + growing);
  }
  // A bore no wider than the rod cannot hold it anywhere.
  double r_o = 0.0;  // the rod's largest outer radius, m
  for (int i = 0; i < kPoints && p.rod.section; ++i)
    r_o = std::max(r_o, 0.5 * p.rod.section->At(p.rod.length * i / (kPoints - 1),
                                                 p.robot.actuation).outer_diameter);
  for (int k = 0; k < contact.count; ++k) {
    const ContactSurface& c = contact.surface[k];
    if (c.shape == ContactSurface::Shape::kCylinder && c.inside && c.radius <= r_o)
      report->Add("environment.contact[" + std::to_string(k) + "].radius",
                  "a bore of radius " + FormatNumber(c.radius) +
                      " m is no wider than the rod (outer radius " + FormatNumber(r_o) +
                      " m): it cannot hold it");
  }
}

}  // namespace cosserat::io::detail
