#include "cosserat/rod/stiffness_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

namespace cosserat {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool Fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

bool Finite(double x) { return std::isfinite(x); }

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

/// A piecewise-linear table has kinks at its knots.
void AppendKnots(const LinearTable& t, std::vector<double>* out) {
  for (double x : t.x()) out->push_back(x);
}

}  // namespace

// --- LinearTable -------------------------------------------------------------------------------

LinearTable::LinearTable(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {}

LinearTable LinearTable::Line(double x0, double y0, double x1, double y1) {
  return LinearTable({x0, x1}, {y0, y1});
}

double LinearTable::operator()(double x) const {
  if (x_.empty()) return 0.0;
  if (!(x > x_.front())) return y_.front();  // also NaN: the first value
  if (x >= x_.back()) return y_.back();
  // First knot greater than x; x_[i-1] <= x < x_[i].
  const std::size_t i = std::upper_bound(x_.begin(), x_.end(), x) - x_.begin();
  const double t = (x - x_[i - 1]) / (x_[i] - x_[i - 1]);
  return y_[i - 1] + t * (y_[i] - y_[i - 1]);
}

double LinearTable::MinValue() const {
  return y_.empty() ? 0.0 : *std::min_element(y_.begin(), y_.end());
}

bool LinearTable::IsNonDecreasing() const {
  for (std::size_t i = 1; i < y_.size(); ++i)
    if (y_[i] < y_[i - 1]) return false;
  return true;
}

bool LinearTable::IsValid(std::string* why) const {
  if (x_.empty()) return Fail(why, "table has no rows");
  if (x_.size() != y_.size()) return Fail(why, "table columns differ in length");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!Finite(x_[i]) || !Finite(y_[i]))
      return Fail(why, "table row " + std::to_string(i) + " is not finite");
    if (i > 0 && !(x_[i] > x_[i - 1]))
      return Fail(why, "table row " + std::to_string(i) + ": x = " + Num(x_[i]) +
                           " is not greater than the previous " + Num(x_[i - 1]));
  }
  return true;
}

// --- ModulusLaw --------------------------------------------------------------------------------

ModulusLaw ModulusLaw::Affine(double E0, double slope) {
  ModulusLaw m;
  m.kind_ = Kind::kAffine;
  m.e0_ = E0;
  m.slope_ = slope;
  return m;
}

ModulusLaw ModulusLaw::Table(LinearTable pressure_to_modulus) {
  ModulusLaw m;
  m.kind_ = Kind::kTable;
  m.table_ = std::move(pressure_to_modulus);
  return m;
}

double ModulusLaw::operator()(double pressure) const {
  const double p = pressure > 0.0 ? pressure : 0.0;
  return kind_ == Kind::kAffine ? e0_ + slope_ * p : table_(p);
}

double ModulusLaw::MinValue() const { return kind_ == Kind::kAffine ? e0_ : table_.MinValue(); }

bool ModulusLaw::IsValid(std::string* why) const {
  if (kind_ == Kind::kAffine) {
    if (!(Finite(e0_) && e0_ >= 0)) return Fail(why, "modulus E0 must be finite and >= 0");
    if (!(Finite(slope_) && slope_ >= 0))
      return Fail(why,
                  "modulus slope must be finite and >= 0 (the law may not fall with pressure)");
    return true;
  }
  std::string reason;
  if (!table_.IsValid(&reason)) return Fail(why, "modulus " + reason);
  if (table_.x().front() < 0) return Fail(why, "modulus table pressures must be >= 0");
  if (table_.MinValue() < 0) return Fail(why, "modulus table values must be >= 0");
  if (!table_.IsNonDecreasing())
    return Fail(why, "modulus table values may not fall with pressure");
  return true;
}

SectionProperties SectionPropertiesWithModulus(const CrossSection& section,
                                               const Material& material, double E) {
  Material m = material;
  const double nu = material.PoissonRatio();
  m.youngs_modulus = E;
  m.shear_modulus = E / (2.0 * (1.0 + nu));
  return UniformSectionProperties(section, m);
}

// --- Interval checks ---------------------------------------------------------------------------

bool IntervalsAreValid(const std::vector<double>& starts, const std::vector<double>& ends,
                       double length, bool require_sorted, const std::string& what,
                       std::string* why) {
  const std::size_t n = starts.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = what + " " + std::to_string(i);
    if (!(Finite(starts[i]) && Finite(ends[i]) && starts[i] >= 0 && ends[i] <= length &&
          starts[i] < ends[i]))
      return Fail(why, name + " must satisfy 0 <= start < end <= length (" + Num(length) +
                           "), got [" + Num(starts[i]) + ", " + Num(ends[i]) + ")");
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  if (!require_sorted)
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return starts[a] < starts[b]; });
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t i = order[k], j = order[k - 1];
    if (starts[i] < ends[j])
      return Fail(why, what + " " + std::to_string(i) + " [" + Num(starts[i]) + ", " +
                           Num(ends[i]) + ") overlaps " + what + " " + std::to_string(j) + " [" +
                           Num(starts[j]) + ", " + Num(ends[j]) + ")" +
                           (require_sorted ? " (they must be sorted by start)" : ""));
  }
  return true;
}

// --- TaperedSection ----------------------------------------------------------------------------

TaperedSection::TaperedSection(LinearTable outer_radius, LinearTable inner_radius,
                               Material material)
    : outer_(std::move(outer_radius)),
      inner_(std::move(inner_radius)),
      material_(std::move(material)) {}

TaperedSection TaperedSection::LinearCircle(double length, double base_radius, double tip_radius,
                                            const Material& material) {
  return TaperedSection(LinearTable::Line(0.0, base_radius, length, tip_radius), LinearTable(),
                        material);
}

TaperedSection TaperedSection::LinearAnnulus(double length, double base_outer, double base_inner,
                                             double tip_outer, double tip_inner,
                                             const Material& material) {
  return TaperedSection(LinearTable::Line(0.0, base_outer, length, tip_outer),
                        LinearTable::Line(0.0, base_inner, length, tip_inner), material);
}

CrossSection TaperedSection::SectionAt(double s) const {
  const double ro = outer_(s);
  return inner_.empty() ? CrossSection::Circle(ro) : CrossSection::Annulus(ro, inner_(s));
}

SectionProperties TaperedSection::At(double s, const Actuation& /*actuation*/) const {
  return UniformSectionProperties(SectionAt(s), material_);
}

std::vector<double> TaperedSection::Breakpoints() const {
  std::vector<double> out;
  AppendKnots(outer_, &out);
  AppendKnots(inner_, &out);
  return out;  // MakeGrid drops those at 0, at L and duplicates
}

bool TaperedSection::IsValid(double length, std::string* why) const {
  std::string reason;
  if (!outer_.IsValid(&reason)) return Fail(why, "taper outer radius " + reason);
  if (!inner_.empty() && !inner_.IsValid(&reason)) return Fail(why, "taper inner radius " + reason);
  if (!material_.IsValid(why)) return false;
  std::vector<double> knots = outer_.x();
  knots.insert(knots.end(), inner_.x().begin(), inner_.x().end());
  for (double s : knots) {
    if (s < 0 || s > length)
      return Fail(why, "taper knot s = " + Num(s) + " lies outside [0, " + Num(length) + "]");
    const double ro = outer_(s);
    if (!(ro > 0))
      return Fail(why, "taper outer radius must be > 0, got " + Num(ro) + " at s = " + Num(s));
    if (!inner_.empty()) {
      const double ri = inner_(s);
      if (!(ri >= 0 && ri < ro))
        return Fail(why, "taper inner radius must be >= 0 and < the outer radius, got " + Num(ri) +
                             " (outer " + Num(ro) + ") at s = " + Num(s));
    }
  }
  return true;
}

// --- PressureModulusSection --------------------------------------------------------------------

PressureModulusSection::PressureModulusSection(CrossSection section, Material material,
                                               ModulusLaw modulus)
    : section_(section), material_(std::move(material)), modulus_(std::move(modulus)) {}

SectionProperties PressureModulusSection::At(double /*s*/, const Actuation& actuation) const {
  return SectionPropertiesWithModulus(section_, material_, modulus_(actuation.pressure));
}

bool PressureModulusSection::IsValid(double /*length*/, std::string* why) const {
  if (!section_.IsValid(why) || !material_.IsValid(why) || !modulus_.IsValid(why)) return false;
  if (!(modulus_.MinValue() > 0))
    return Fail(why, "pressure modulus E_eff(p) must be > 0 at every pressure");
  return true;
}

// --- JammingSection ----------------------------------------------------------------------------

JammingSection::JammingSection(std::shared_ptr<const SectionProfile> tube,
                               std::vector<JammingSegment> segments)
    : tube_(std::move(tube)), segments_(std::move(segments)) {}

int JammingSection::SegmentAt(double s) const {
  for (std::size_t k = 0; k < segments_.size(); ++k)
    if (s >= segments_[k].start && s < segments_[k].end) return static_cast<int>(k);
  return -1;
}

double JammingSection::LayerBendingStiffness(int k, const Actuation& actuation) const {
  if (k < 0 || k >= static_cast<int>(segments_.size()) || k >= Actuation::kMaxSegments) return 0;
  const JammingSegment& seg = segments_[k];
  return seg.layer_modulus(actuation.jamming_pressure[k]) * seg.layer_I;
}

double JammingSection::BendingStiffness(int k, const Actuation& actuation) const {
  const JammingSegment& seg = segments_.at(k);
  return At(0.5 * (seg.start + seg.end), actuation).stiffness(0, 0);
}

double JammingSection::StiffnessRatio(int a, int b, const Actuation& actuation) const {
  return BendingStiffness(a, actuation) / BendingStiffness(b, actuation);
}

SectionProperties JammingSection::At(double s, const Actuation& actuation) const {
  SectionProperties p = tube_->At(s, actuation);
  const int k = SegmentAt(s);
  if (k >= 0) {
    const double layer = LayerBendingStiffness(k, actuation);
    p.stiffness(0, 0) += layer;
    p.stiffness(1, 1) += layer;
  }
  return p;
}

std::vector<double> JammingSection::Breakpoints() const {
  std::vector<double> out = tube_->Breakpoints();
  for (const JammingSegment& seg : segments_) {
    out.push_back(seg.start);
    out.push_back(seg.end);
  }
  return out;
}

bool JammingSection::IsValid(double length, std::string* why) const {
  if (!tube_) return Fail(why, "jamming tube profile is missing");
  if (!tube_->IsValid(length, why)) return false;
  if (segments_.empty()) return Fail(why, "jamming profile has no segments");
  if (segments_.size() > static_cast<std::size_t>(Actuation::kMaxSegments))
    return Fail(why, "jamming profile has " + std::to_string(segments_.size()) +
                         " segments, more than Actuation::kMaxSegments (" +
                         std::to_string(Actuation::kMaxSegments) + ")");
  std::vector<double> starts, ends;
  for (const JammingSegment& seg : segments_) {
    starts.push_back(seg.start);
    ends.push_back(seg.end);
  }
  if (!IntervalsAreValid(starts, ends, length, true, "jamming segment", why)) return false;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const JammingSegment& seg = segments_[k];
    if (!(Finite(seg.layer_I) && seg.layer_I > 0))
      return Fail(why, "jamming segment " + std::to_string(k) + ": layer_I must be > 0");
    std::string reason;
    if (!seg.layer_modulus.IsValid(&reason))
      return Fail(why, "jamming segment " + std::to_string(k) + ": layer " + reason);
  }
  return true;
}

// --- Inflated tubes ----------------------------------------------------------------------------

double InflatedWrinklingMoment(double pressure, double radius) {
  return 0.5 * kPi * pressure * radius * radius * radius;
}

double InflatedCollapseMoment(double pressure, double radius) {
  return kPi * pressure * radius * radius * radius;
}

InflatedTubeSection::InflatedTubeSection(double radius, double wall_thickness,
                                         ModulusLaw wall_modulus, double poisson_ratio,
                                         double wall_density,
                                         std::vector<Constriction> constrictions,
                                         KelvinVoigtDamping damping)
    : radius_(radius),
      wall_thickness_(wall_thickness),
      modulus_(std::move(wall_modulus)),
      poisson_ratio_(poisson_ratio),
      density_(wall_density),
      constrictions_(std::move(constrictions)),
      damping_(damping) {}

const InflatedTubeSection::Constriction* InflatedTubeSection::ConstrictionAt(double s) const {
  for (const Constriction& c : constrictions_)
    if (s >= c.start && s < c.end) return &c;
  return nullptr;
}

double InflatedTubeSection::RadiusAt(double s) const {
  const Constriction* c = ConstrictionAt(s);
  return c ? c->diameter_ratio * radius_ : radius_;
}

double InflatedTubeSection::BendingStiffnessAt(double s, const Actuation& actuation) const {
  return At(s, actuation).stiffness(0, 0);
}

double InflatedTubeSection::WrinklingMomentAt(double s, const Actuation& actuation) const {
  return InflatedWrinklingMoment(actuation.pressure, RadiusAt(s));
}

SectionProperties InflatedTubeSection::At(double s, const Actuation& actuation) const {
  const double r = radius_, t = wall_thickness_, nu = poisson_ratio_;
  const double E = modulus_(actuation.pressure);
  const double G = E / (2.0 * (1.0 + nu));
  const double A = 2.0 * kPi * r * t;    // wall area
  const double I = kPi * r * r * r * t;  // thin-wall second moment about a diameter
  const double kappa = 2.0 * (1.0 + nu) / (4.0 + 3.0 * nu);
  const double p = actuation.pressure > 0.0 ? actuation.pressure : 0.0;
  const Constriction* c = ConstrictionAt(s);
  const double r_local = c ? c->diameter_ratio * r : r;
  const double alpha = c ? c->factor : 1.0;
  const double pressure_shear = p * kPi * r_local * r_local;  // Fichter's P = p π r²
  // Suulker et al. 2026: EI_eff(s) = {α(s) E_eff(p)} I(s): the band scales the modulus by α and the
  // second moment follows the local diameter, I(s) = π r(s)³ t (the wall keeps its thickness, area
  // and mass: a band gathers the film, it does not remove it).
  const double I_local = kPi * r_local * r_local * r_local * t;
  SectionProperties out;
  out.stiffness = Vec6(alpha * E * I_local, alpha * E * I_local, alpha * G * 2.0 * I_local,
                       kappa * G * A + pressure_shear, kappa * G * A + pressure_shear, E * A)
                      .asDiagonal();
  const double rho = density_;
  out.mass = Vec6(rho * I, rho * I, rho * 2.0 * I, rho * A, rho * A, rho * A).asDiagonal();
  const KelvinVoigtDamping& d = damping_;
  out.damping = Vec6(d.bending, d.bending, d.torsion, d.shear, d.shear, d.extension).asDiagonal();
  out.outer_diameter = 2.0 * r_local;
  return out;
}

std::vector<double> InflatedTubeSection::Breakpoints() const {
  std::vector<double> out;
  for (const Constriction& c : constrictions_) {
    out.push_back(c.start);
    out.push_back(c.end);
  }
  return out;
}

bool InflatedTubeSection::IsValid(double length, std::string* why) const {
  if (!(Finite(radius_) && radius_ > 0)) return Fail(why, "inflated tube radius must be > 0");
  if (!(Finite(wall_thickness_) && wall_thickness_ > 0 && wall_thickness_ < radius_))
    return Fail(why, "inflated tube wall_thickness must be > 0 and < the radius");
  if (!(poisson_ratio_ > -1 && poisson_ratio_ <= 0.5))
    return Fail(why, "inflated tube poisson_ratio must lie in (-1, 0.5]");
  if (!(Finite(density_) && density_ >= 0))
    return Fail(why, "inflated tube wall density must be finite and >= 0");
  for (double d : {damping_.bending, damping_.torsion, damping_.shear, damping_.extension})
    if (!(Finite(d) && d >= 0)) return Fail(why, "damping coefficients must be finite and >= 0");
  std::string reason;
  if (!modulus_.IsValid(&reason)) return Fail(why, "inflated tube wall " + reason);
  if (!(modulus_.MinValue() > 0))
    return Fail(why, "inflated tube E_eff(p) must be > 0 at every pressure");
  std::vector<double> starts, ends;
  for (const Constriction& c : constrictions_) {
    starts.push_back(c.start);
    ends.push_back(c.end);
  }
  if (!IntervalsAreValid(starts, ends, length, false, "constriction", why)) return false;
  for (std::size_t k = 0; k < constrictions_.size(); ++k) {
    const Constriction& c = constrictions_[k];
    if (!(c.diameter_ratio > 0 && c.diameter_ratio <= 1))
      return Fail(why, "constriction " + std::to_string(k) + ": diameter_ratio must lie in (0, 1]");
    if (!(Finite(c.factor) && c.factor > 0))
      return Fail(why, "constriction " + std::to_string(k) + ": factor must be > 0");
  }
  return true;
}

// --- FixedActuationSection ---------------------------------------------------------------------

FixedActuationSection::FixedActuationSection(std::shared_ptr<const SectionProfile> inner,
                                             const Actuation& actuation)
    : inner_(std::move(inner)), actuation_(actuation) {}

SectionProperties FixedActuationSection::At(double s, const Actuation& /*actuation*/) const {
  return inner_->At(s, actuation_);
}

bool FixedActuationSection::IsValid(double length, std::string* why) const {
  if (!inner_) return Fail(why, "profile is missing");
  return inner_->IsValid(length, why);
}

}  // namespace cosserat
