#pragma once
/// \file
/// Linear elastic, isotropic material with optional Kelvin–Voigt damping.

#include <string>

namespace cosserat {

/// Sectional Kelvin–Voigt damping coefficients: the diagonal of D in
/// Λ = −K(ξ − ξ*) − D ∂ξ/∂t (FD notes 2025, eq. 16). Units: bending and torsion N·m²·s,
/// shear and extension N·s.
struct KelvinVoigtDamping {
  double bending = 0.0;
  double torsion = 0.0;
  double shear = 0.0;
  double extension = 0.0;
};

struct Material {
  double youngs_modulus = 0.0;  ///< E, Pa
  double shear_modulus = 0.0;   ///< G, Pa
  double density = 0.0;         ///< ρ, kg/m³
  KelvinVoigtDamping damping;

  static Material FromShearModulus(double E, double G, double density);
  /// G = E / (2 (1 + ν)).
  static Material FromPoissonRatio(double E, double poisson_ratio, double density);

  /// ν = E / (2G) − 1.
  double PoissonRatio() const { return youngs_modulus / (2.0 * shear_modulus) - 1.0; }

  bool IsValid(std::string* why) const;
};

}  // namespace cosserat
