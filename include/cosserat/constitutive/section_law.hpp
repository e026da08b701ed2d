#pragma once
/// \file
/// The linear Kelvin–Voigt law of a section, the one constitutive law both formulations use:
///   W = K (ξ − ξ*) + D ξ̇,   and in statics ξ = ξ* + K⁻¹ W,
/// with W = [m; n] the internal wrench (N·m; N), ξ = [K; Γ] the strain (1/m; –), body frame
/// (Antman 2005, ch. 8; Till, Aloi & Rucker 2019, eq. 8). K, D and the mass M per unit length are
/// sampled from the rod's SectionProfile.
///
/// Chambers (constitutive/chamber_law.hpp) enter here and nowhere else: their actuation wrench w,
/// constant in the body frame, shifts the rest strain, ξ* = ξ*_rod + K⁻¹ w, so W(ξ) is the
/// wrench of rod and fluid together and every solver that samples SectionLaw takes them.
///
/// Sections must be principal-axes: K, D and M diagonal. Coupling between bending, shear and
/// stretch is refused, by every solver, with the one error of `SectionLaw::At`. Why refused and
/// not supported: every stiffness profile (bands, taper, E_eff(p), jamming, inflated tubes) and
/// every problem file gives principal-axes sections; the Lang & Linn discretisation keeps bending
/// at the vertices and shear and stretch at the segment midpoints, so a coupling term has no place
/// in it; and in the implicit BDF2 law a coupled K + c0 D would need a 6 × 6 solve per stage.

#include <string>

#include "cosserat/lie/types.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat {

struct SectionLaw {
  Vec6 stiffness = Vec6::Ones();  ///< diag K = [EI₁, EI₂, GJ, κGA, κGA, EA] (N·m², N)
  Vec6 damping = Vec6::Zero();    ///< diag D, units of K times s
  Vec6 mass = Vec6::Ones();       ///< diag M = [ρI₁, ρI₂, ρJ, ρA, ρA, ρA] per unit length
  Vec6 rest_strain = Vec6::Zero();  ///< ξ*, with the chambers' shift K⁻¹ w (1/m; –)
  double outer_diameter = 0.0;      ///< m (SectionProperties::outer_diameter)

  /// The section of `rod` at s (m) under `actuation` (stiffness profiles and chamber pressures
  /// read it). Throws std::invalid_argument naming s when
  /// K, D or M has an off-diagonal entry (see the file comment).
  static SectionLaw At(const RodModel& rod, double s, const Actuation& actuation);

  /// W = K (ξ − ξ*) + D ξ̇ (N·m; N).
  Vec6 Wrench(const Vec6& strain, const Vec6& strain_rate) const {
    return stiffness.cwiseProduct(strain - rest_strain) + damping.cwiseProduct(strain_rate);
  }
  /// ξ = ξ* + K⁻¹ W, the static strain under the wrench W.
  Vec6 StaticStrain(const Vec6& wrench) const {
    return rest_strain + wrench.cwiseQuotient(stiffness);
  }
  /// ρA, kg/m.
  double mass_per_length() const { return mass(5); }
};

/// True when K, D and M of p are diagonal (a principal-axes section); else writes which is not.
bool IsPrincipalAxes(const SectionProperties& p, std::string* why);

/// rod.section->At(s, actuation), refused as SectionLaw::At refuses a coupled section: what
/// solvers that work with the matrices (blocks of K, M) call instead of the profile itself.
SectionProperties PrincipalAxesSectionAt(const RodModel& rod, double s, const Actuation& actuation);

}  // namespace cosserat
