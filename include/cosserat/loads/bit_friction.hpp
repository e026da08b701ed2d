#pragma once
/// \file
/// The friction torque of a drill bit on the rock, about the rod's tangent at the tip (body z):
/// Coulomb friction that weakens with the spin rate (Stribeck-type), regularised near zero spin
/// so that it is smooth. Velocity weakening at the bit drives torsional stick-slip (Brett 1992);
/// the exponential decay from the static to the kinetic coefficient is the bit model of
/// Navarro-López & Cortés 2007:
///   T(ω) = −c ω − W R μ(ω) ω / ω̄,  ω̄ = sqrt(ω² + ω_ε²),  μ(ω) = μ_k + (μ_s − μ_k) exp(−ω̄ / ω_s)
/// with W the weight on bit (N), R the bit radius (m), ω the tip's spin about its axis (rad/s,
/// body frame), c a viscous torque coefficient (the mud around the bit and the bottom-hole
/// assembly). The falling friction feeds torsional oscillations; c damps them, so that above a
/// table speed where the friction's slope is below c the string turns steadily. Below ω_ε the bit creeps instead of sticking exactly; above a few ω_s the
/// torque is the kinetic W R μ_k. A plain aggregate (part of StaticLoads); zero in statics,
/// where nothing spins.

#include <string>

namespace cosserat {

struct BitFriction {
  double weight_on_bit = 0.0;        ///< W, N; 0: no bit friction
  double radius = 0.0;               ///< R, m
  double static_coefficient = 0.0;   ///< μ_s
  double kinetic_coefficient = 0.0;  ///< μ_k (≤ μ_s: the torque weakens with speed)
  double stribeck_velocity = 1.0;    ///< ω_s, rad/s
  double regularisation = 1e-2;      ///< ω_ε, rad/s
  double viscous = 0.0;              ///< c, N·m·s/rad

  bool present() const { return weight_on_bit > 0.0 && radius > 0.0; }
  /// T(ω) (N·m about body z) and, with dtorque, dT/dω (N·m·s).
  double Torque(double spin, double* dtorque = nullptr) const;
  /// Checks the fields; on failure writes "<field>: <why>".
  bool IsValid(std::string* why) const;
  bool operator==(const BitFriction& o) const {
    return weight_on_bit == o.weight_on_bit && radius == o.radius &&
           static_coefficient == o.static_coefficient &&
           kinetic_coefficient == o.kinetic_coefficient &&
           stribeck_velocity == o.stribeck_velocity && regularisation == o.regularisation &&
           viscous == o.viscous;
  }
};

}  // namespace cosserat
