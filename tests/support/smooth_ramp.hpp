#pragma once
// Test support: the ramp the dynamics tests switch loads on with, so that it excites no mode the
// coarse time steps cannot resolve.

namespace cosserat::testing {

/// u⁴ (35 − 84u + 70u² − 20u³) on [0, 1]: rises from 0 to 1 with its first three derivatives zero
/// at both ends. The caller clamps u to [0, 1].
inline double SmoothRamp(double u) {
  return u * u * u * u * (35 - 84 * u + 70 * u * u - 20 * u * u * u);
}

}  // namespace cosserat::testing
