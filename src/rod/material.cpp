#include "cosserat/rod/material.hpp"

#include <cmath>

namespace cosserat {

Material Material::FromShearModulus(double E, double G, double density) {
  Material m;
  m.youngs_modulus = E;
  m.shear_modulus = G;
  m.density = density;
  return m;
}

Material Material::FromPoissonRatio(double E, double poisson_ratio, double density) {
  return FromShearModulus(E, E / (2.0 * (1.0 + poisson_ratio)), density);
}

bool Material::IsValid(std::string* why) const {
  auto fail = [&](const std::string& msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0))
    return fail("youngs_modulus must be a finite positive number");
  if (!(std::isfinite(shear_modulus) && shear_modulus > 0))
    return fail("shear_modulus must be a finite positive number");
  if (!(std::isfinite(density) && density >= 0)) return fail("density must be finite and >= 0");
  const double nu = PoissonRatio();
  if (!(nu > -1.0 && nu <= 0.5 + 1e-12))
    return fail("shear_modulus implies a Poisson ratio outside (-1, 0.5]");
  for (double d : {damping.bending, damping.torsion, damping.shear, damping.extension})
    if (!(std::isfinite(d) && d >= 0)) return fail("damping coefficients must be finite and >= 0");
  return true;
}

}  // namespace cosserat
