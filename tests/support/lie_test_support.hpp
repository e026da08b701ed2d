#pragma once
// Shared by the Lie-group tests: constants, tolerances and seeded random draws.

#include <random>

#include "cosserat/lie/types.hpp"

namespace cosserat::lie::testing {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 2.220446049250313e-16;  // double machine epsilon
constexpr int kCases = 200;                     // random cases per property

// Round-off budget for a chain of a few dozen flops on O(1)–O(10) numbers (exp, log, products,
// conversions): observed ≤ 2e-15, so 1e-13 (≈ 450 eps) leaves a factor 50. A genuine error in a
// formula (wrong coefficient, sign, block, index or branch) shows up at 1e-4 or worse.
constexpr double kTight = 1e-13;

// Central differences with step h: truncation h²/6 |f'''| ≈ 1e-12 and round-off ≈ eps |f| / h ≈
// 1e-9 for |f| ≲ 10, so analytic and numerical Jacobians agree to ~1e-9 relative. 1e-6 leaves
// three orders of margin, and a wrong term in a Jacobian is an O(θ) or O(|v|) error for the
// random inputs, far above it.
constexpr double kFdStep = 1e-6;
constexpr double kFdTol = 1e-6;

// Unit vector, uniform on the sphere.
inline Vec3 RandomAxis(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

// Rotation vector with angle uniform in [0, max_angle), rad.
inline Vec3 RandomRotVec(std::mt19937& rng, double max_angle) {
  return std::uniform_real_distribution<double>(0.0, max_angle)(rng) * RandomAxis(rng);
}

}  // namespace cosserat::lie::testing
