#pragma once
// Torsional vibration of a shaft clamped at one end with a rigid disc at the other: the drill
// string with its bottom-hole assembly. With c = sqrt(GJ / (ρ I_p)) the torsional wave speed,
// the natural frequencies satisfy (ωL/c) tan(ωL/c) = J_string / J_disc, J_string = ρ I_p L the
// string's polar inertia (Timoshenko, Young & Weaver, Vibration Problems in Engineering, 1974,
// the shaft with a disc at its end).

#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// The first torsional natural frequency (rad/s): the root x of x tan x = ratio in (0, π/2),
/// ω = x c / L. \param ratio J_string / J_disc (> 0); c wave speed (m/s); L length (m).
inline double ShaftWithDiscFirstOmega(double ratio, double c, double L) {
  const double x = Bisect([&](double y) { return y * std::tan(y) - ratio; }, 1e-12, kPi / 2 - 1e-12);
  return x * c / L;
}

}  // namespace cosserat::truth
