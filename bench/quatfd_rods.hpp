#pragma once
// The two benchmark rods of the quaternion-FD path (bench_quatfd.cpp, diagnostics/).

#include "cosserat/lie/se3.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat::bench {

/// (a) Rubber rod: L = 0.5 m, r = 5 mm, E = 5 MPa, ν = 0.5, ρ = 1100 kg/m³, clamped horizontally.
/// Antman (Kelvin–Voigt) damping on all four strain rates with one retardation time, C̃ = τ C,
/// τ = 0.01 s: light on the first bending mode (ζ1 = ω1 τ/2 ≈ 1.2 %, ω1 = 2.35 rad/s), strong on
/// extension and shear (ζ ≥ 1 from the axial fundamental, 212 rad/s, up), as in Lang & Linn's
/// benchmarks ("strong damping on the extensional and shearing dof").
inline RodModel RubberRod() {
  Material m = Material::FromPoissonRatio(5e6, 0.5, 1100);
  const CrossSection c = CrossSection::Circle(0.005);
  const double tau = 0.01;
  m.damping.bending = tau * m.youngs_modulus * c.I1;
  m.damping.torsion = tau * m.shear_modulus * c.torsion_constant;
  m.damping.shear = tau * m.shear_modulus * c.area;
  m.damping.extension = tau * m.youngs_modulus * c.area;
  return RodModel::Uniform(0.5, c, m);
}

/// (b) Steel string: L = 1 m, r = 0.5 mm, E = 200 GPa, G = 80 GPa, ρ = 7850 kg/m³. Damping on
/// shear and extension only (Lang & Linn 2009), C̃ = τ C with τ = 10 µs: critical for the highest
/// axial mode of the 20-segment grid (2c/Δs = 2.0e5 rad/s), over-damped for the
/// shear/rotary-inertia modes (~1e7 rad/s); a pendulum swinging at ~3 rad/s is not affected
/// (ζ ~ 1e-5).
inline RodModel SteelString() {
  Material m = Material::FromShearModulus(200e9, 80e9, 7850);
  const CrossSection c = CrossSection::Circle(0.0005);
  const double tau = 1e-5;
  m.damping.shear = tau * m.shear_modulus * c.area;
  m.damping.extension = tau * m.youngs_modulus * c.area;
  return RodModel::Uniform(1.0, c, m);
}

inline lie::SE3 Horizontal() {
  lie::SE3 base;  // rod tangent (body z) along world +x
  base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  return base;
}

}  // namespace cosserat::bench
