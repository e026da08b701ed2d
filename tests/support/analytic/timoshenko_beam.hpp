#pragma once
// Small static deflections of uniform beams: Euler–Bernoulli bending plus Timoshenko's shear
// deflection (Timoshenko 1921, Phil. Mag. 41, 744–746; deflection tables of Gere & Timoshenko,
// Mechanics of Materials, 1997, appendix G). kGA = κ G A is the shear stiffness (N); pass
// infinity for the Euler–Bernoulli value alone.

#include <cmath>

namespace cosserat::truth {

/// Tip deflection (m) of a cantilever under a transverse tip load P (N): P L³/(3 E I) + P L/(κGA).
inline double CantileverTipDeflection(double P, double L, double EI, double kGA) {
  return P * L * L * L / (3 * EI) + P * L / kGA;
}

/// The bending part of the tip deflection when the bent length and lever arm are L(1 + ε) (a rod
/// pre-stretched by ε), plus the shear part over L: P (1 + ε)² L³/(3 E I) + P L/S. Used for the
/// inflated beam, whose shear stiffness S = p π r² + κGA carries Fichter's pressure term
/// (Fichter 1966, NASA TN D-3466).
inline double PrestretchedCantileverTipDeflection(double P, double L, double EI, double S,
                                                  double eps) {
  return P * (1 + eps) * (1 + eps) * L * L * L / (3 * EI) + P * L / S;
}

/// Mid-span deflections (m) under a uniform lateral load q (N/m), no axial force. Shear adds
/// q L²/(8 κGA) at mid-span of the clamped–clamped and the pinned–pinned beam.
inline double ClampedClampedUniformLoadMidSpan(double q, double L, double EI, double kGA) {
  return q * L * L * L * L / (384 * EI) + q * L * L / (8 * kGA);
}
inline double PinnedPinnedUniformLoadMidSpan(double q, double L, double EI, double kGA) {
  return 5 * q * L * L * L * L / (384 * EI) + q * L * L / (8 * kGA);
}
/// Clamped at s = 0, pinned at L (propped cantilever), Euler–Bernoulli only:
/// y = q x² (L − x)(3L − 2x)/(48 E I), q L⁴/(192 E I) at mid-span.
inline double ClampedPinnedUniformLoadMidSpan(double q, double L, double EI) {
  return q * L * L * L * L / (192 * EI);
}

}  // namespace cosserat::truth
