#include "cosserat/strong/shooting_exponent.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat {

double SingleShootingExponent(const RodModel& rod, double dt, const Actuation& actuation) {
  const double c0 = 1.5 / dt;  // BDF2: ∂/∂t ≈ c0 (·)_{n+1} + history, 1/s
  constexpr int kPieces = 200;
  const double h = rod.length / kPieces;
  double sum = 0.0;
  for (int i = 0; i < kPieces; ++i) {
    const SectionProperties p = rod.section->At((i + 0.5) * h, actuation);
    const double ei = p.min_bending_stiffness();  // N·m²
    const double rho_a = p.mass(3, 3);                                 // kg/m
    sum += std::pow(c0 * c0 * rho_a / ei, 0.25) * h;
  }
  return sum;
}

int SuggestedShootingSegments(double exponent) {
  return std::max(1, static_cast<int>(std::ceil(exponent / 5.0)));
}

}  // namespace cosserat
