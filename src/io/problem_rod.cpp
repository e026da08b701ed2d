#include "problem_rod.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosserat/rod/filled_pipe_section.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "problem_profile.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;


// --- rod.section -------------------------------------------------------------------------------

struct ShapeKeys {
  std::string shape;
  std::vector<std::string> keys;  ///< besides "shape"
};

const std::vector<ShapeKeys>& SectionShapes() {
  static const std::vector<ShapeKeys> shapes = {
      {"circle", {"radius"}},
      {"annulus", {"outer_radius", "inner_radius", "contents_density"}},
      {"rectangle", {"width", "height"}},
      {"explicit", {"area", "I1", "I2", "J", "shear_coefficient", "outer_diameter"}},
  };
  return shapes;
}

/// The keys allowed for `shape`; for every shape when it is unknown.
std::vector<std::string> SectionKeys(const std::optional<std::string>& shape) {
  std::vector<std::string> keys{"shape"};
  for (const ShapeKeys& s : SectionShapes())
    if (!shape || s.shape == *shape) keys.insert(keys.end(), s.keys.begin(), s.keys.end());
  return keys;
}

std::vector<std::string> SectionShapeNames() {
  std::vector<std::string> names;
  for (const ShapeKeys& s : SectionShapes()) names.push_back(s.shape);
  return names;
}

/// "shape" if given; a section without one is explicit when it names any explicit property.
std::optional<std::string> SectionShape(const ObjectReader& s) {
  if (s.Has("shape")) return ReadChoice(s, "shape", SectionShapeNames(), Presence::kRequired);
  for (const char* key : {"area", "I1", "I2", "J"})
    if (s.Has(key)) return std::string("explicit");
  s.report().Missing(s.PathOf("shape"),
                     "one of " + QuotedList(SectionShapeNames()) +
                         " (or the explicit properties \"area\", \"I1\", \"I2\", \"J\")");
  return std::nullopt;
}

std::optional<CrossSection> ParseAnnulus(const ObjectReader& s) {
  const auto outer = ReadNumber(s, "outer_radius", PositiveNumber(), Presence::kRequired);
  const auto inner = ReadNumber(s, "inner_radius", NonNegativeNumber(), Presence::kRequired);
  if (!outer || !inner) return std::nullopt;
  if (*inner >= *outer) {
    s.Reject("inner_radius", "a number smaller than outer_radius (" + FormatNumber(*outer) + ")");
    return std::nullopt;
  }
  return CrossSection::Annulus(*outer, *inner);
}

std::optional<CrossSection> ParseExplicitSection(const ObjectReader& s) {
  const auto area = ReadNumber(s, "area", PositiveNumber(), Presence::kRequired);
  const auto I1 = ReadNumber(s, "I1", PositiveNumber(), Presence::kRequired);
  const auto I2 = ReadNumber(s, "I2", PositiveNumber(), Presence::kRequired);
  const auto J = ReadNumber(s, "J", PositiveNumber(), Presence::kRequired);
  const auto kappa = ReadNumber(s, "shear_coefficient", PositiveNumber(), Presence::kOptional);
  const auto d_o = ReadNumber(s, "outer_diameter", PositiveNumber(), Presence::kOptional);
  if (!area || !I1 || !I2 || !J || (s.Has("shear_coefficient") && !kappa) ||
      (s.Has("outer_diameter") && !d_o))
    return std::nullopt;
  // The area must fit in the outline's disc (a pipe's steel is less than its full disc).
  if (d_o && *area > M_PI * *d_o * *d_o / 4 * (1 + 1e-12)) {
    s.Reject("outer_diameter", "a diameter whose disc holds the area " + FormatNumber(*area) +
                                   " m² (at least " +
                                   FormatNumber(std::sqrt(4 * *area / M_PI)) + " m)");
    return std::nullopt;
  }
  return CrossSection::Explicit(*area, *I1, *I2, *J, kappa.value_or(1.0), d_o.value_or(0.0));
}

/// A section built from valid dimensions can still be degenerate: a radius of 1e-300 m has an
/// area that underflows to 0. Named at the section, instead of the rod's check later.
std::optional<CrossSection> Checked(const ObjectReader& s, std::optional<CrossSection> c) {
  std::string why;
  if (c && !c->IsValid(&why)) {
    s.report().Add(s.path(), why + " (the dimensions under- or overflow in double precision)");
    return std::nullopt;
  }
  return c;
}

std::optional<CrossSection> ParseSection(const ObjectReader& s) {
  const std::optional<std::string> shape = SectionShape(s);
  if (!shape) {
    s.AllowOnly(SectionKeys(std::nullopt));
    return std::nullopt;
  }
  s.AllowOnly(SectionKeys(shape), "for a " + Quote(*shape) + " section");
  if (*shape == "circle") {
    const auto r = ReadNumber(s, "radius", PositiveNumber(), Presence::kRequired);
    if (!r) return std::nullopt;
    return Checked(s, CrossSection::Circle(*r));
  }
  if (*shape == "annulus") return Checked(s, ParseAnnulus(s));
  if (*shape == "rectangle") {
    const auto w = ReadNumber(s, "width", PositiveNumber(), Presence::kRequired);
    const auto h = ReadNumber(s, "height", PositiveNumber(), Presence::kRequired);
    if (!w || !h) return std::nullopt;
    return Checked(s, CrossSection::Rectangle(*w, *h));
  }
  return ParseExplicitSection(s);
}

// --- rod.material ------------------------------------------------------------------------------

std::optional<KelvinVoigtDamping> ParseDamping(const ObjectReader& d) {
  d.AllowOnly({"bending", "torsion", "shear", "extension"});
  KelvinVoigtDamping out;
  bool ok = true;
  auto read = [&](const char* key, double* target) {
    const auto x = ReadNumber(d, key, NonNegativeNumber(), Presence::kOptional);
    if (x) *target = *x;
    ok = ok && (x || !d.Has(key));
  };
  read("bending", &out.bending);
  read("torsion", &out.torsion);
  read("shear", &out.shear);
  read("extension", &out.extension);
  if (!ok) return std::nullopt;
  return out;
}

/// The shear modulus, from "shear_modulus" or "poisson_ratio" (exactly one must be given).
std::optional<double> ParseShearModulus(const ObjectReader& m, std::optional<double> E) {
  const bool has_G = m.Has("shear_modulus"), has_nu = m.Has("poisson_ratio");
  if (has_G == has_nu) {
    m.report().Expected(m.path(), R"(exactly one of "shear_modulus" and "poisson_ratio")",
                        has_G ? "both" : "neither");
  }
  const NumberRule poisson{"a number in (-1, 0.5]", [](double nu) { return nu > -1 && nu <= 0.5; }};
  const auto G =
      has_G ? ReadNumber(m, "shear_modulus", PositiveNumber(), Presence::kOptional) : std::nullopt;
  const auto nu =
      has_nu ? ReadNumber(m, "poisson_ratio", poisson, Presence::kOptional) : std::nullopt;
  if (has_G == has_nu || !E) return std::nullopt;
  if (has_nu) {
    if (!nu) return std::nullopt;
    const double shear = *E / (2.0 * (1.0 + *nu));
    if (!(shear >= std::numeric_limits<double>::min())) {  // E/(2(1 + ν)) underflows
      m.report().Expected(m.PathOf("youngs_modulus"),
                          "a modulus whose shear modulus E/(2(1 + ν)) is a normal double",
                          FormatNumber(*E) + " Pa (shear modulus " + FormatNumber(shear) + ")");
      return std::nullopt;
    }
    return shear;
  }
  if (!G) return std::nullopt;
  const double implied_nu = *E / (2.0 * *G) - 1.0;
  if (implied_nu > 0.5 + 1e-12) {
    m.report().Expected(
        m.PathOf("shear_modulus"),
        "at least youngs_modulus / 3 = " + FormatNumber(*E / 3.0) + " (a Poisson ratio <= 0.5)",
        Describe(*m.Find("shear_modulus")) + " (Poisson ratio " + FormatNumber(implied_nu) + ")");
    return std::nullopt;
  }
  if (!(implied_nu > -1.0)) {  // E ≪ G: E / (2G) underflows
    m.report().Expected(m.path(),
                        "youngs_modulus and shear_modulus whose Poisson ratio E/(2G) − 1 is above −1",
                        "E = " + FormatNumber(*E) + " Pa and G = " + FormatNumber(*G) +
                            " Pa (Poisson ratio " + FormatNumber(implied_nu) + ")");
    return std::nullopt;
  }
  return *G;
}

std::optional<Material> ParseMaterial(const ObjectReader& m) {
  m.AllowOnly({"youngs_modulus", "shear_modulus", "poisson_ratio", "density", "damping"});
  const auto E = ReadNumber(m, "youngs_modulus", PositiveNumber(), Presence::kRequired);
  const auto G = ParseShearModulus(m, E);
  const auto rho = ReadNumber(m, "density", NonNegativeNumber(), Presence::kRequired);
  std::optional<KelvinVoigtDamping> damping = KelvinVoigtDamping{};
  if (m.Has("damping")) {
    const auto d = ReadObject(m, "damping", Presence::kOptional);
    damping = d ? ParseDamping(*d) : std::nullopt;
  }
  if (!E || !G || !rho || !damping) return std::nullopt;
  Material out = Material::FromShearModulus(*E, *G, *rho);
  out.damping = *damping;
  return out;
}

}  // namespace

int InteriorBreakpoints(std::vector<double> cuts, double length) {
  std::sort(cuts.begin(), cuts.end());
  const double eps = 1e-12 * length;
  double last = 0.0;
  int count = 0;
  for (double c : cuts)
    if (c > eps && c < length - eps && c - last > eps) last = c, ++count;
  return count;
}

/// "contents_density" of an annulus: the fluid filling its bore (FilledPipeSection), kg/m³.
void FillPipe(const ObjectReader& s, bool has_profile, const std::optional<CrossSection>& section,
              Problem* problem) {
  const auto density = ReadNumber(s, "contents_density", NonNegativeNumber(), Presence::kOptional);
  if (has_profile) {
    s.report().Add(s.PathOf("contents_density"),
                   "is read without a rod.stiffness_profile in this version (the bore would "
                   "follow the profile)");
    return;
  }
  if (!density || !section || !problem->rod.section) return;
  const double bore = M_PI * section->inner_radius * section->inner_radius;  // m²
  problem->rod.section =
      std::make_shared<FilledPipeSection>(problem->rod.section, *density * bore);
}

void ParseRod(const ObjectReader& rod, Problem* problem) {
  rod.AllowOnly({"length", "nodes", "section", "material", "rest_curvature", "stiffness_profile"});
  const auto length = ReadNumber(rod, "length", PositiveNumber(), Presence::kRequired);
  const auto nodes = ReadInteger(rod, "nodes", 3, kMaxRodNodes, Presence::kRequired);
  const auto section_object = ReadObject(rod, "section", Presence::kRequired);
  const auto section = section_object ? ParseSection(*section_object) : std::nullopt;
  const auto material_object = ReadObject(rod, "material", Presence::kRequired);
  const auto material = material_object ? ParseMaterial(*material_object) : std::nullopt;
  const auto rest_curvature = ReadVec3(rod, "rest_curvature", Presence::kOptional);
  const auto profile = ParseStiffnessProfile(rod, ProfileBase{length, section, material});

  if (nodes && length && profile && *profile) {
    const int needed = 2 + InteriorBreakpoints((*profile)->Breakpoints(), *length);
    if (*nodes < needed)
      rod.Reject("nodes", "at least " + std::to_string(needed) +
                              " (a node at each end and at every stiffness_profile breakpoint "
                              "inside the rod: band, segment and constriction ends, table knots)");
  }
  if (length && section && material && profile) {
    problem->rod = RodModel::Uniform(*length, *section, *material);
    if (*profile) {
      problem->rod.section = *profile;
      std::string why;
      if (!problem->rod.IsValid(&why))  // the parser's checks should have caught it
        rod.report().Add(rod.PathOf("stiffness_profile"), why);
    }
  }
  if (rest_curvature) problem->rod.rest_strain = ConstantRestCurvature(*rest_curvature);
  problem->nodes = nodes.value_or(problem->nodes);
  if (section_object && section_object->Has("contents_density"))
    FillPipe(*section_object, rod.Has("stiffness_profile"), section, problem);
  if (section && !rod.Has("stiffness_profile")) {
    problem->bore_area = M_PI * section->inner_radius * section->inner_radius;
    problem->bore_filled = section_object->Has("contents_density");
  }
}

}  // namespace cosserat::io::detail
