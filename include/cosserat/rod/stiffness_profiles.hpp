#pragma once
/// \file
/// Stiffness profiles for soft and continuum robots (Suulker et al. 2026; Do et al. 2023): tapering
/// sections, a pressure-dependent modulus E_eff(p), layer jamming, thin-walled inflated tubes with
/// constrictive bands, and the wrinkling (kink) moment of an inflated tube.
///
/// Every profile is a SectionProfile: At(s, actuation) is const, allocates nothing and reads only
/// the Actuation fields it documents, so a solver may re-sample it whenever the actuation changes
/// (switchable per-segment states). Profile breakpoints (jumps, and kinks of piecewise-linear
/// tables) become grid nodes. Units are SI throughout; pressures are gauge pressures in Pa.

#include <memory>
#include <string>
#include <vector>

#include "cosserat/rod/section_profile.hpp"

namespace cosserat {

// --- Tables and modulus laws -------------------------------------------------------------------

/// y(x), piecewise linear through the knots (x_i, y_i) with x strictly increasing, and held
/// constant beyond the first and last knot (no extrapolation). Evaluation is a binary search: no
/// allocation, safe to share between threads.
class LinearTable {
 public:
  LinearTable() = default;
  LinearTable(std::vector<double> x, std::vector<double> y);
  /// A straight line from (x0, y0) to (x1, y1), x0 < x1.
  static LinearTable Line(double x0, double y0, double x1, double y1);

  double operator()(double x) const;
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  bool empty() const { return x_.empty(); }
  double MinValue() const;  ///< smallest y (the extremes of a piecewise-linear function)
  bool IsNonDecreasing() const;

  /// At least one knot, x and y of equal size, every number finite, x strictly increasing.
  bool IsValid(std::string* why) const;

 private:
  std::vector<double> x_, y_;
};

/// A modulus as a function of a pressure, E(p) (Pa → Pa): the effective modulus E_eff(p) of a
/// pressurised body (Suulker et al. 2026: EI(s) = α(s) E_eff(p) I(s)) or the layer modulus E_ℓ(ΔP)
/// of a jammed stack. Pressures below zero are evaluated as zero. Laws must not fall with pressure
/// (IsValid), so the stiffness built from them rises monotonically with pressure.
class ModulusLaw {
 public:
  enum class Kind { kAffine, kTable };
  ModulusLaw() = default;  ///< E(p) = 0
  /// E(p) = E (Pa), whatever the pressure.
  static ModulusLaw Constant(double E) { return Affine(E, 0.0); }
  /// E(p) = E0 + slope · p: E0 in Pa, slope dimensionless (Pa of modulus per Pa of pressure). The
  /// affine fit is the usual empirical model of an inflated fabric beam's effective modulus
  /// (Suulker et al. 2026 fit E_eff(p) from tip-deflection tests) and of a jammed layer stack at
  /// moderate ΔP (Do et al. 2023); it is a fit, not a derivation.
  static ModulusLaw Affine(double E0, double slope);
  /// A measured table of (p, E): p in Pa (>= 0, strictly increasing), E in Pa, linear between
  /// knots, held at the end values outside them.
  static ModulusLaw Table(LinearTable pressure_to_modulus);

  double operator()(double pressure) const;  ///< Pa
  Kind kind() const { return kind_; }
  double E0() const { return e0_; }
  double slope() const { return slope_; }
  const LinearTable& table() const { return table_; }
  /// The smallest modulus over p >= 0 (Pa): E0 for an affine law, the smallest knot of a table.
  double MinValue() const;

  /// Finite; E(p) >= 0; non-decreasing in p (slope >= 0, table E non-decreasing); table
  /// pressures >= 0 and strictly increasing.
  bool IsValid(std::string* why) const;

 private:
  Kind kind_ = Kind::kAffine;
  double e0_ = 0.0, slope_ = 0.0;
  LinearTable table_;
};

/// Sectional properties of `section` made of `material` with its Young's modulus replaced by E
/// (Pa) and the shear modulus by E / (2(1 + ν)), ν the material's Poisson ratio. Density and
/// damping as in `material`.
SectionProperties SectionPropertiesWithModulus(const CrossSection& section,
                                               const Material& material, double E);

// --- Tapering ----------------------------------------------------------------------------------

/// A circle or annulus whose radii vary along s, piecewise linearly through the knots of tables
/// over s (m → m): A(s), I(s), J(s), the shear coefficient and the mass all follow the local
/// section (CrossSection::Circle / Annulus at r(s)). Interior knots are breakpoints (the radius
/// has a kink there), so RK4 never steps across one. Reads no actuation.
class TaperedSection final : public SectionProfile {
 public:
  /// outer_radius(s) (m); inner_radius(s) (m), an empty table for a solid circle.
  TaperedSection(LinearTable outer_radius, LinearTable inner_radius, Material material);
  /// Solid circle, radius linear from base_radius at s = 0 to tip_radius at s = length (m).
  static TaperedSection LinearCircle(double length, double base_radius, double tip_radius,
                                     const Material& material);
  /// Annulus, both radii linear from s = 0 to s = length (m).
  static TaperedSection LinearAnnulus(double length, double base_outer, double base_inner,
                                      double tip_outer, double tip_inner, const Material& material);

  CrossSection SectionAt(double s) const;
  SectionProperties At(double s, const Actuation& actuation) const override;
  std::vector<double> Breakpoints() const override;
  /// Valid tables and material; every radius finite, outer > 0, 0 <= inner < outer at every knot
  /// (the radii are piecewise linear, so the knots bound them); knots within [0, length].
  bool IsValid(double length, std::string* why) const override;

  const LinearTable& outer_radius() const { return outer_; }
  const LinearTable& inner_radius() const { return inner_; }
  const Material& material() const { return material_; }

 private:
  LinearTable outer_, inner_;
  Material material_;
};

// --- Pressure-dependent modulus ----------------------------------------------------------------

/// A fixed section whose Young's modulus is E_eff(p) of the inflation pressure p =
/// actuation.pressure (Suulker et al. 2026: EI = E_eff(p) I). Every stiffness entry follows
/// (SectionPropertiesWithModulus); the mass does not depend on p.
class PressureModulusSection final : public SectionProfile {
 public:
  /// `material` gives ν (its E and G), the density and the damping; its E is not used.
  PressureModulusSection(CrossSection section, Material material, ModulusLaw modulus);
  double ModulusAt(double pressure) const { return modulus_(pressure); }  ///< Pa
  SectionProperties At(double s, const Actuation& actuation) const override;
  /// Valid section, material and law, and E_eff(p) > 0 for every p >= 0.
  bool IsValid(double length, std::string* why) const override;
  const CrossSection& section() const { return section_; }
  const ModulusLaw& modulus() const { return modulus_; }

 private:
  CrossSection section_;
  Material material_;
  ModulusLaw modulus_;
};

// --- Layer jamming -----------------------------------------------------------------------------

/// One switchable layer-jamming segment [start, end) (Do et al. 2023):
/// EI_eff(ΔP) = EI_tube(P_int) + E_ℓ(ΔP) I_ℓ, with ΔP = actuation.jamming_pressure[k] for the k-th
/// segment of the list.
struct JammingSegment {
  double start = 0.0;        ///< m
  double end = 0.0;          ///< m
  double layer_I = 0.0;      ///< I_ℓ, second moment of area of the jammed stack, m⁴ (> 0)
  ModulusLaw layer_modulus;  ///< E_ℓ(ΔP), Pa; E_ℓ(0) is the compliant (unjammed) value
};

/// A tube profile (any SectionProfile, e.g. PressureModulusSection for EI_tube(P_int)) with
/// switchable jamming segments. In segment k both bending stiffnesses get E_ℓ(ΔP_k) I_ℓ added;
/// torsion, shear, stretch and mass are the tube's. Segment ends are breakpoints.
class JammingSection final : public SectionProfile {
 public:
  JammingSection(std::shared_ptr<const SectionProfile> tube, std::vector<JammingSegment> segments);

  /// The segment holding s (start <= s < end), or −1.
  int SegmentAt(double s) const;
  /// E_ℓ(ΔP_k) I_ℓ of segment k, N·m².
  double LayerBendingStiffness(int k, const Actuation& actuation) const;
  /// EI1 at the middle of segment k, N·m².
  double BendingStiffness(int k, const Actuation& actuation) const;
  /// EI1(segment a) / EI1(segment b), at their midpoints.
  double StiffnessRatio(int a, int b, const Actuation& actuation) const;

  SectionProperties At(double s, const Actuation& actuation) const override;
  std::vector<double> Breakpoints() const override;
  /// Valid tube; 1 … Actuation::kMaxSegments segments, each 0 <= start < end <= length, sorted by
  /// start and not overlapping; I_ℓ > 0; a valid layer law.
  bool IsValid(double length, std::string* why) const override;
  const std::vector<JammingSegment>& segments() const { return segments_; }

 private:
  std::shared_ptr<const SectionProfile> tube_;
  std::vector<JammingSegment> segments_;
};

// --- Inflated beams (eversion / vine robots) ---------------------------------------------------

/// Moment (N·m) at which the wall of a thin inflated tube first goes slack and wrinkles, for gauge
/// pressure p (Pa) and tube radius r (m): M_w = π p r³ / 2 (Comer & Levy 1963, membrane tube,
/// wall stress p r / 2 axially cancelled on the compressed side). Beyond it the tube kinks.
double InflatedWrinklingMoment(double pressure, double radius);
/// Moment (N·m) at which the wrinkle spreads round the whole section and the tube collapses:
/// M_c = π p r³ (Comer & Levy 1963), twice the wrinkling moment.
double InflatedCollapseMoment(double pressure, double radius);

/// A thin-walled inflated tube (wall thickness t ≪ radius r), with optional constrictive bands.
///
/// Section (thin wall): A = 2π r t, I1 = I2 = π r³ t, J = 2π r³ t. Stiffness with E = E_eff(p),
/// p = actuation.pressure, G = E / (2(1 + ν)), κ = 2(1 + ν)/(4 + 3ν) (Cowper, thin ring):
///   K = diag(E I, E I, G J, κ G A + p π r², κ G A + p π r², E A).
/// The p π r² added to the shear stiffness is Fichter's pressure term (Fichter 1966, NASA TN
/// D-3466: shear stiffness P + κ G A with P = p π r²). Bending stiffness E_eff(p) I rises
/// monotonically with p because the law is non-decreasing. Mass: the wall, ρ_wall per unit volume.
///
/// A constriction [start, end) narrows the tube to diameter_ratio · r there (which lowers the
/// wrinkling moment and the pressure term); bending and torsion stiffness are Suulker et al.'s
/// EI_eff(s) = {α(s) E_eff(p)} I(s): the empirical modulus factor α (≈ 0.36 for a band that
/// halves the diameter) times the second moment at the local radius, I(s) = π r(s)³ t. Area and
/// mass stay those of the full wall. Constriction ends are breakpoints.
class InflatedTubeSection final : public SectionProfile {
 public:
  struct Constriction {
    double start = 0.0;           ///< m
    double end = 0.0;             ///< m
    double diameter_ratio = 1.0;  ///< local diameter / nominal, in (0, 1]
    double factor = 1.0;          ///< α, the modulus factor of bending and torsion there, > 0
  };
  /// radius r and wall_thickness t in m (t < r); wall_modulus E_eff(p); poisson_ratio ν of the
  /// wall; wall_density in kg/m³.
  InflatedTubeSection(double radius, double wall_thickness, ModulusLaw wall_modulus,
                      double poisson_ratio, double wall_density,
                      std::vector<Constriction> constrictions = {},
                      KelvinVoigtDamping damping = {});

  /// Local radius r(s) (m): diameter_ratio · r inside a constriction.
  double RadiusAt(double s) const;
  /// E I1 at s for the actuation's pressure, N·m².
  double BendingStiffnessAt(double s, const Actuation& actuation) const;
  /// InflatedWrinklingMoment(actuation.pressure, RadiusAt(s)), N·m.
  double WrinklingMomentAt(double s, const Actuation& actuation) const;

  SectionProperties At(double s, const Actuation& actuation) const override;
  std::vector<double> Breakpoints() const override;
  /// 0 < t < r, ν in (−1, 0.5], ρ >= 0, damping >= 0, valid law with E_eff(p) > 0 for p >= 0;
  /// constrictions inside [0, length], not overlapping, ratio in (0, 1], α > 0.
  bool IsValid(double length, std::string* why) const override;

  double radius() const { return radius_; }
  double wall_thickness() const { return wall_thickness_; }
  const ModulusLaw& wall_modulus() const { return modulus_; }
  const std::vector<Constriction>& constrictions() const { return constrictions_; }
  double poisson_ratio() const { return poisson_ratio_; }
  double density() const { return density_; }
  const KelvinVoigtDamping& damping() const { return damping_; }

 private:
  const Constriction* ConstrictionAt(double s) const;
  double radius_, wall_thickness_;
  ModulusLaw modulus_;
  double poisson_ratio_, density_;
  std::vector<Constriction> constrictions_;
  KelvinVoigtDamping damping_;
};

// --- A fixed actuation -------------------------------------------------------------------------

/// A profile evaluated at one fixed actuation, whatever At() is given. Problem files state the
/// pressures their profile is solved at (the format has no actuation block yet); the parser wraps
/// the profile in this. Robot code that drives the actuation should use the inner profile.
class FixedActuationSection final : public SectionProfile {
 public:
  FixedActuationSection(std::shared_ptr<const SectionProfile> inner, const Actuation& actuation);
  SectionProperties At(double s, const Actuation& actuation) const override;
  std::vector<double> Breakpoints() const override { return inner_->Breakpoints(); }
  bool IsValid(double length, std::string* why) const override;
  const std::shared_ptr<const SectionProfile>& inner() const { return inner_; }
  const Actuation& actuation() const { return actuation_; }

 private:
  std::shared_ptr<const SectionProfile> inner_;
  Actuation actuation_;
};

// --- Checks shared by the band-like profiles ---------------------------------------------------

/// True if the intervals [start_i, end_i) are finite, within [0, length], each start < end, and,
/// in the given order, sorted and not overlapping (start_i >= end_{i−1}). `what` names an item in
/// the message ("band", "segment", ...), which gives its index.
bool IntervalsAreValid(const std::vector<double>& starts, const std::vector<double>& ends,
                       double length, bool require_sorted, const std::string& what,
                       std::string* why);

}  // namespace cosserat
