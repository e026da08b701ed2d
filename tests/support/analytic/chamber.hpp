#pragma once
// Rods with pressurised chambers (soft pneumatic actuators, Polygerinos et al. 2015): a chamber
// at offset d (m) from the neutral axis, of area A (m²), at gauge pressure p (Pa) pushes the
// sections apart with p A at the lever d, so a weightless rod takes the constant strain
//   κ = −p A d / EI  (bending away from the chamber),   Γ3 = 1 + p A / EA  (stretch),
// and its centreline is a circular arc. κ is per unit reference arc length s; the deformed
// length is Γ3 L, so the arc's geometric radius is Γ3 / |κ|.

#include <cmath>

#include "cosserat/lie/types.hpp"

namespace cosserat::truth {

/// Body curvature (1/m, per unit reference length) of one chamber: p A d / EI (EI in N·m²).
inline double ChamberArcCurvature(double p, double A, double d, double EI) {
  return p * A * d / EI;
}

/// Pressure (Pa) for which that arc turns the tip by theta (rad) over the length L.
inline double ChamberPressureForTurn(double theta, double EI, double L, double A, double d) {
  return theta * EI / (L * A * d);
}

/// Stretch Γ3 (–) of the pressures' total axial force F = Σ p A (N) on an axial stiffness EA (N).
inline double ChamberStretch(double F, double EA) { return 1 + F / EA; }

/// Pose after an arc of length s (m, reference) of constant curvature k about body y (1/m,
/// signed: k < 0 bends towards −x) and stretch nu, starting at the origin along +z: the
/// position (ν/k)(1 − cos ks, 0, sin ks) and the rotation about y by k s.
struct ArcPose {
  Vec3 p;
  Mat3 R;
};
inline ArcPose BodyYArc(double k, double nu, double s) {
  ArcPose out;
  const double c = std::cos(k * s), sn = std::sin(k * s);
  out.p = k == 0 ? Vec3(0, 0, nu * s) : Vec3(nu / k * (1 - c), 0, nu / k * sn);
  out.R << c, 0, sn, 0, 1, 0, -sn, 0, c;
  return out;
}

}  // namespace cosserat::truth
