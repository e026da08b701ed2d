#pragma once
// Inflated thin-walled circular tubes (eversion robots): the bending moment at which the wall
// first wrinkles and the one at which the tube collapses. Source: Comer & Levy (1963), AIAA J. 1,
// 1652–1655, "Deflections of an inflated circular-cylindrical cantilever beam". The inflated
// cantilever's small tip deflection (Fichter 1966) is PrestretchedCantileverTipDeflection in
// timoshenko_beam.hpp.

#include "roots.hpp"

namespace cosserat::truth {

/// Wrinkling moment (N·m) of a tube of radius r (m) at gauge pressure p (Pa): M_w = π p r³/2.
inline double WrinklingMoment(double p, double r) { return 0.5 * kPi * p * r * r * r; }

/// Collapse moment (N·m): M_c = π p r³ = 2 M_w.
inline double CollapseMoment(double p, double r) { return 2 * WrinklingMoment(p, r); }

}  // namespace cosserat::truth
