#pragma once
// Shared by the Lie-group tests: constants and seeded random draws.

#include <random>

#include "cosserat/lie/types.hpp"

namespace cosserat::lie::testing {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 2.220446049250313e-16;  // double machine epsilon
constexpr int kCases = 200;                     // random cases per property

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
