#include "bending_stress_report.hpp"

#include <cmath>

#include "cosserat/rod/filled_pipe_section.hpp"
#include "cosserat/rod/section_profile.hpp"

namespace cosserat::run::detail {

namespace {

/// The outer fibre's bending stress (Pa) under the body-frame bending moments m1, m2 (N·m) the
/// section's material carries.
double OuterFibreStress(const CrossSection& c, double m1, double m2) {
  switch (c.shape) {
    case SectionShape::kCircle:
    case SectionShape::kAnnulus:
      return std::hypot(m1, m2) * c.outer_radius / c.I1;
    case SectionShape::kRectangle:  // M1 about body x bends across the height (along y)
      return std::abs(m1) * 0.5 * c.height / c.I1 + std::abs(m2) * 0.5 * c.width / c.I2;
    case SectionShape::kExplicit:
      break;
  }
  return std::hypot(m1 / c.I1, m2 / c.I2) * 0.5 * c.OuterDiameter();
}

}  // namespace

void AddBendingStressReport(const io::Problem& problem, Result* result) {
  auto& json = result->json;
  if (!json.contains("nodes") || !json["nodes"].contains("moment_body")) return;
  const SectionProfile* profile = problem.rod.section.get();
  if (const auto* filled = dynamic_cast<const FilledPipeSection*>(profile))
    profile = &filled->pipe();  // the contents carry no stress
  const auto* uniform = dynamic_cast<const UniformSection*>(profile);
  if (uniform == nullptr) return;
  const CrossSection& section = uniform->section();
  const double E = uniform->material().youngs_modulus;
  const auto& s = json["nodes"]["s"];
  const auto& curvature = json["nodes"]["curvature"];
  nlohmann::ordered_json stress = nlohmann::ordered_json::array();
  double stress_max = -1.0, stress_s = 0.0, kappa_max = -1.0, kappa_s = 0.0;
  for (std::size_t i = 0; i < curvature.size(); ++i) {
    // The material's own bending moments E I (κ − κ*): with tendons or chambers the section's
    // resultant moment is not the backbone's (a tendon's pull balances it: zero, under no load,
    // on a backbone bent to 239 MPa).
    const Vec6 rest = problem.rod.RestStrainAt(s[i].get<double>());
    const double d1 = curvature[i][0].get<double>() - rest(0);
    const double d2 = curvature[i][1].get<double>() - rest(1);
    const double sigma = OuterFibreStress(section, E * section.I1 * d1, E * section.I2 * d2);
    stress.push_back(sigma);
    if (sigma > stress_max) {
      stress_max = sigma;
      stress_s = s[i].get<double>();
    }
    const double kappa = std::hypot(d1, d2);  // the change of curvature
    if (kappa > kappa_max) {
      kappa_max = kappa;
      kappa_s = s[i].get<double>();
    }
  }
  json["nodes"]["bending_stress"] = stress;
  json["bending"] = {{"max_stress", stress_max},
                     {"max_stress_s", stress_s},
                     {"max_curvature", kappa_max},
                     {"max_curvature_s", kappa_s}};
}

}  // namespace cosserat::run::detail
