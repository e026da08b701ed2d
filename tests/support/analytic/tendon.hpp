#pragma once
// Tendon-driven rods in Rucker & Webster's model (Rucker & Webster 2011, IEEE Trans. Robotics 27,
// "Statics and dynamics of continuum robots with general tendon routing and external loading"):
// a straight tendon at a constant offset bends the rod into a circular arc, a helical one twists
// it against its handedness.

#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// Curvature (1/m) of the arc a straight tendon at offset d (m) from the neutral axis under
/// tension tau (N) gives a rod of bending stiffness EI (N·m²): the tendon's pull is a tip moment
/// τ d, so κ = τ d / E I.
inline double TendonArcCurvature(double tau, double d, double EI) { return tau * d / EI; }

/// Tension (N) for which that arc turns the tip by theta (rad) over the length L: θ E I/(L d).
inline double TendonTensionForTurn(double theta, double EI, double L, double d) {
  return theta * EI / (L * d);
}

/// Radius (m) of the centreline of that arc when the rod also stretches: the tendon compresses it
/// by τ/EA, Γ = (1 − τ/EA) e3, so the radius is (1 − τ/EA)/κ. EA axial stiffness (N).
inline double TendonArcRadius(double tau, double d, double EI, double EA) {
  return (1 - tau / EA) / TendonArcCurvature(tau, d, EI);
}

/// Small-tension twist (rad) at the tip of a rod of length L with a helical tendon of radius rho
/// (m) and pitch (m, signed: positive right-handed): the tendon's tangent has a hoop part, so its
/// pull on the guides is a torque −τ ρ² w e3/|q| with w = 2π/pitch, and the rod twists by
/// θ ≈ −τ ρ² w L /(G J sqrt(1 + ρ² w²)), to first order in τ. GJ torsional stiffness (N·m²).
inline double HelicalTendonTwist(double tau, double rho, double pitch, double L, double GJ) {
  const double w = 2 * kPi / pitch;
  return -tau * rho * rho * w * L / (GJ * std::sqrt(1 + rho * rho * w * w));
}

}  // namespace cosserat::truth
