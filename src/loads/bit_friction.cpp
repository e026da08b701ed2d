#include "cosserat/loads/bit_friction.hpp"

#include <cmath>

namespace cosserat {

double BitFriction::Torque(double spin, double* dtorque) const {
  if (!present()) {
    if (dtorque) *dtorque = 0.0;
    return 0.0;
  }
  const double WR = weight_on_bit * radius;
  const double bar = std::sqrt(spin * spin + regularisation * regularisation);
  const double decay = std::exp(-bar / stribeck_velocity);
  const double mu = kinetic_coefficient + (static_coefficient - kinetic_coefficient) * decay;
  const double direction = spin / bar;  // ω / ω̄
  if (dtorque) {
    // d(ω/ω̄)/dω = ω_ε²/ω̄³; dμ/dω = −(μ_s − μ_k) e^{−ω̄/ω_s} (ω/ω̄) / ω_s.
    const double d_direction = regularisation * regularisation / (bar * bar * bar);
    const double d_mu = -(static_coefficient - kinetic_coefficient) * decay * direction /
                        stribeck_velocity;
    *dtorque = -WR * (d_mu * direction + mu * d_direction) - viscous;
  }
  return -WR * mu * direction - viscous * spin;
}

bool BitFriction::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(weight_on_bit) && weight_on_bit >= 0))
    return fail("weight_on_bit: expected a finite number >= 0");
  if (!(std::isfinite(radius) && radius >= 0)) return fail("radius: expected a finite number >= 0");
  if (!(std::isfinite(kinetic_coefficient) && kinetic_coefficient >= 0))
    return fail("kinetic_coefficient: expected a finite number >= 0");
  if (!(std::isfinite(static_coefficient) && static_coefficient >= kinetic_coefficient))
    return fail("static_coefficient: expected a finite number >= the kinetic coefficient");
  if (!(std::isfinite(stribeck_velocity) && stribeck_velocity > 0))
    return fail("stribeck_velocity: expected a finite number > 0");
  if (!(std::isfinite(regularisation) && regularisation > 0))
    return fail("regularisation: expected a finite number > 0");
  if (!(std::isfinite(viscous) && viscous >= 0)) return fail("viscous: expected a finite number >= 0");
  return true;
}

}  // namespace cosserat
