#pragma once
/// \file
/// Sectional stiffness K(s), mass M(s) and damping D(s) along the rod, as functions of the arc
/// length s (m) and of the actuation state.
///
/// Strain ordering (FD notes 2025, eq. 7): ξ = [K; Γ] = [κ1, κ2, κ3, Γ1, Γ2, Γ3]: bending about
/// body x and y, torsion, shear along x and y, stretch. K = diag(E I1, E I2, G J, κ G A, κ G A,
/// E A) for a principal-axes section (N·m², N·m², N·m², N, N, N).

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/cross_section.hpp"
#include "cosserat/rod/material.hpp"

namespace cosserat {

struct SectionProperties {
  Mat6 stiffness = Mat6::Identity();  ///< K(s), body frame, see file comment for units
  Mat6 mass = Mat6::Identity();  ///< M(s) per unit length: diag(ρI1, ρI2, ρ(I1+I2), ρA, ρA, ρA)
  Mat6 damping = Mat6::Zero();  ///< D(s), Kelvin–Voigt, units of K times s
  double outer_diameter = 0.0;  ///< m: what the section displaces in a fluid and touches with

  /// The smaller and the larger of the bending stiffnesses E I1, E I2 (N·m²).
  double min_bending_stiffness() const { return std::min(stiffness(0, 0), stiffness(1, 1)); }
  double max_bending_stiffness() const { return std::max(stiffness(0, 0), stiffness(1, 1)); }
};

/// Sectional properties of the (unactuated) uniform section.
SectionProperties UniformSectionProperties(const CrossSection& section, const Material& material);

/// Interface: the section at s for an actuation state. Implementations must be thread-safe
/// (const, no mutable state) so two solvers can share one.
class SectionProfile {
 public:
  virtual ~SectionProfile() = default;
  virtual SectionProperties At(double s, const Actuation& actuation) const = 0;
  /// Interior arc lengths (0 < s < L, m) where the properties jump; the grid puts nodes there.
  virtual std::vector<double> Breakpoints() const { return {}; }
  /// Validate against the rod length; on failure write the reason.
  virtual bool IsValid(double length, std::string* why) const = 0;
};

/// The same section and material along the whole rod.
class UniformSection final : public SectionProfile {
 public:
  UniformSection(CrossSection section, Material material);
  SectionProperties At(double s, const Actuation& actuation) const override;
  bool IsValid(double length, std::string* why) const override;
  const CrossSection& section() const { return section_; }
  const Material& material() const { return material_; }

 private:
  CrossSection section_;
  Material material_;
  SectionProperties properties_;
};

/// Bands [start, end) in which the bending and torsion stiffness are multiplied by a factor α
/// (Suulker et al. 2026: EI(s) = α(s) E I; α ≈ 0.36 for a band that halves the diameter). Outside
/// the bands, the base profile. Band ends become grid nodes. Bands must lie within [0, L] and must
/// not overlap (IsValid); more profiles are in stiffness_profiles.hpp.
class BandedSection final : public SectionProfile {
 public:
  struct Band {
    double start = 0.0;   ///< m
    double end = 0.0;     ///< m
    double factor = 1.0;  ///< α, dimensionless, > 0
  };
  BandedSection(std::shared_ptr<const SectionProfile> base, std::vector<Band> bands);
  SectionProperties At(double s, const Actuation& actuation) const override;
  std::vector<double> Breakpoints() const override;
  bool IsValid(double length, std::string* why) const override;

 private:
  std::shared_ptr<const SectionProfile> base_;
  std::vector<Band> bands_;
};

}  // namespace cosserat
