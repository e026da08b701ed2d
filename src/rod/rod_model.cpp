#include "cosserat/rod/rod_model.hpp"

#include <algorithm>
#include <cmath>

#include "cosserat/rod/stiffness_profiles.hpp"

namespace cosserat {

SectionProperties UniformSectionProperties(const CrossSection& c, const Material& m) {
  const double E = m.youngs_modulus, G = m.shear_modulus, rho = m.density;
  const double kappa = c.ShearCoefficient(m.PoissonRatio());
  SectionProperties p;
  p.stiffness = Vec6(E * c.I1, E * c.I2, G * c.torsion_constant, kappa * G * c.area,
                     kappa * G * c.area, E * c.area)
                    .asDiagonal();
  p.mass =
      Vec6(rho * c.I1, rho * c.I2, rho * c.PolarMoment(), rho * c.area, rho * c.area, rho * c.area)
          .asDiagonal();
  const KelvinVoigtDamping& d = m.damping;
  p.damping = Vec6(d.bending, d.bending, d.torsion, d.shear, d.shear, d.extension).asDiagonal();
  p.outer_diameter = c.OuterDiameter();
  return p;
}

UniformSection::UniformSection(CrossSection section, Material material)
    : section_(section),
      material_(material),
      properties_(UniformSectionProperties(section, material)) {}

SectionProperties UniformSection::At(double /*s*/, const Actuation& /*actuation*/) const {
  return properties_;
}

bool UniformSection::IsValid(double /*length*/, std::string* why) const {
  return section_.IsValid(why) && material_.IsValid(why);
}

BandedSection::BandedSection(std::shared_ptr<const SectionProfile> base, std::vector<Band> bands)
    : base_(std::move(base)), bands_(std::move(bands)) {}

SectionProperties BandedSection::At(double s, const Actuation& actuation) const {
  SectionProperties p = base_->At(s, actuation);
  for (const Band& b : bands_) {
    if (s >= b.start && s < b.end) {
      p.stiffness.topLeftCorner<3, 3>() *= b.factor;  // bending and torsion rows/cols
      p.stiffness.topRightCorner<3, 3>() *= std::sqrt(b.factor);
      p.stiffness.bottomLeftCorner<3, 3>() *= std::sqrt(b.factor);
    }
  }
  return p;
}

std::vector<double> BandedSection::Breakpoints() const {
  std::vector<double> out = base_->Breakpoints();
  for (const Band& b : bands_) {
    out.push_back(b.start);
    out.push_back(b.end);
  }
  return out;
}

bool BandedSection::IsValid(double length, std::string* why) const {
  if (!base_ || !base_->IsValid(length, why)) return false;
  std::vector<double> starts, ends;
  for (const Band& b : bands_) {
    starts.push_back(b.start);
    ends.push_back(b.end);
  }
  if (!IntervalsAreValid(starts, ends, length, false, "band", why)) return false;
  for (std::size_t i = 0; i < bands_.size(); ++i) {
    if (!(std::isfinite(bands_[i].factor) && bands_[i].factor > 0)) {
      if (why) *why = "band " + std::to_string(i) + " factor must be a finite positive number";
      return false;
    }
  }
  return true;
}

Vec6 StraightRestStrain() {
  Vec6 xi = Vec6::Zero();
  xi(5) = 1.0;
  return xi;
}

RestStrainFunction ConstantRestCurvature(const Vec3& curvature) {
  Vec6 xi = StraightRestStrain();
  xi.head<3>() = curvature;
  return [xi](double) { return xi; };
}

RodModel RodModel::Uniform(double length, const CrossSection& section, const Material& material) {
  RodModel m;
  m.length = length;
  m.section = std::make_shared<UniformSection>(section, material);
  return m;
}

bool RodModel::IsValid(std::string* why) const {
  if (!(std::isfinite(length) && length > 0)) {
    if (why) *why = "length must be a finite positive number";
    return false;
  }
  if (!section) {
    if (why) *why = "section profile is missing";
    return false;
  }
  if (tendons.size() > static_cast<size_t>(Actuation::kMaxTendons)) {
    if (why) *why = "at most " + std::to_string(Actuation::kMaxTendons) + " tendons";
    return false;
  }
  for (size_t i = 0; i < tendons.size(); ++i) {
    std::string reason;
    if (!tendons[i].route.IsValid(&reason)) {
      if (why) *why = "tendon " + std::to_string(i) + ": " + reason;
      return false;
    }
    const double anchor = tendons[i].anchor;
    if (!(std::isfinite(anchor) && anchor >= 0.0 && anchor <= length)) {
      if (why) *why = "tendon " + std::to_string(i) + ": anchor must lie in [0, length] (0: the tip)";
      return false;
    }
  }
  if (chambers.size() > static_cast<size_t>(Actuation::kMaxChambers)) {
    if (why) *why = "at most " + std::to_string(Actuation::kMaxChambers) + " chambers";
    return false;
  }
  for (size_t j = 0; j < chambers.size(); ++j) {
    std::string reason;
    if (!chambers[j].IsValid(length, &reason)) {
      if (why) *why = "chamber " + std::to_string(j) + ": " + reason;
      return false;
    }
  }
  return section->IsValid(length, why);
}

std::vector<double> RodModel::Breakpoints() const {
  std::vector<double> out = section ? section->Breakpoints() : std::vector<double>{};
  for (const Chamber& c : chambers) {
    out.push_back(c.start);
    out.push_back(c.end);
  }
  for (const Tendon& t : tendons)
    if (t.anchor > 0.0 && t.anchor < length) out.push_back(t.anchor);
  return out;
}

}  // namespace cosserat
