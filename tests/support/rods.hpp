#pragma once
// Test support: the uniform steel rod of circular section most verification tests are built on
// (E = 200 GPa, G = 80 GPa, ρ = 8000 kg/m³), straight along +z from the origin, with the
// stiffnesses the analytic references in support/analytic/ take as arguments. Tests pick the
// length and radius: e.g. SteelRod{1.0, 0.005}, the slender column (r/L = 1/200).

#include "cosserat/rod/cross_section.hpp"
#include "cosserat/rod/material.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat::testing {

/// Structural steel: E = 200 GPa, G = 80 GPa (ν = 0.25), ρ = 8000 kg/m³.
inline Material Steel() { return Material::FromShearModulus(200e9, 80e9, 8000); }

/// Steel with Kelvin–Voigt damping of one retardation time tau (s) on every strain rate of the
/// section c: bending τ E I, torsion τ G J, shear τ G A (no shear coefficient), extension τ E A.
inline Material DampedSteel(const CrossSection& c, double tau) {
  Material m = Steel();
  m.damping.bending = tau * m.youngs_modulus * c.I1;
  m.damping.torsion = tau * m.shear_modulus * c.torsion_constant;
  m.damping.shear = tau * m.shear_modulus * c.area;
  m.damping.extension = tau * m.youngs_modulus * c.area;
  return m;
}

struct SteelRod {
  double length = 1.0;  ///< m
  double r = 0.005;     ///< radius of the circular section, m
  Material material = Steel();

  CrossSection section() const { return CrossSection::Circle(r); }
  double EI() const { return material.youngs_modulus * section().I1; }               ///< N·m²
  double EA() const { return material.youngs_modulus * section().area; }             ///< N
  double GJ() const { return material.shear_modulus * section().torsion_constant; }  ///< N·m²
  double rhoA() const { return material.density * section().area; }                  ///< kg/m
  /// κ G A (N), with the section's shear coefficient at the material's Poisson ratio.
  double kGA() const {
    return section().ShearCoefficient(material.PoissonRatio()) * material.shear_modulus *
           section().area;
  }
  RodModel model() const { return RodModel::Uniform(length, section(), material); }
};

}  // namespace cosserat::testing
