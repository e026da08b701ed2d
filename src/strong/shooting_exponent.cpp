#include "cosserat/strong/shooting_exponent.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat {

namespace {

// ∫₀ᴸ μ(s) ds by the midpoint rule on 200 pieces, with μ⁴ EI = T μ² + c0² ρA and T(s) ≥ 0 (N).
template <typename Tension>
double Exponent(const RodModel& rod, double dt, const Actuation& actuation, Tension tension) {
  const double c0 = 1.5 / dt;  // BDF2: ∂/∂t ≈ c0 (·)_{n+1} + history, 1/s (0 for dt = ∞)
  constexpr int kPieces = 200;
  const double h = rod.length / kPieces;
  double sum = 0.0;
  for (int i = 0; i < kPieces; ++i) {
    const double s = (i + 0.5) * h;
    const SectionProperties p = rod.section->At(s, actuation);
    const double ei = p.min_bending_stiffness();  // N·m²
    const double rho_a = p.mass(3, 3);            // kg/m
    const double T = std::max(0.0, tension(s));
    const double mu2 = (T + std::sqrt(T * T + 4.0 * ei * c0 * c0 * rho_a)) / (2.0 * ei);
    sum += std::sqrt(mu2) * h;
  }
  return sum;
}

}  // namespace

double SingleShootingExponent(const RodModel& rod, double dt, const Actuation& actuation) {
  return Exponent(rod, dt, actuation, [](double) { return 0.0; });
}

double SingleShootingExponent(const RodModel& rod, double dt, const Actuation& actuation,
                              const RodState& state) {
  const int n = state.size();
  int i = 0;  // the samples come in increasing s
  auto tension = [&](double s) {
    // The body z force at s, linear between the nodes that bracket it.
    while (i + 2 < n && state.s[i + 1] < s) ++i;
    const double t = std::clamp((s - state.s[i]) / (state.s[i + 1] - state.s[i]), 0.0, 1.0);
    const double T = (1.0 - t) * state.wrench_B[i](5) + t * state.wrench_B[i + 1](5);
    return std::isfinite(T) ? T : 0.0;
  };
  return n < 2 ? SingleShootingExponent(rod, dt, actuation) : Exponent(rod, dt, actuation, tension);
}

int SuggestedShootingSegments(double exponent) {
  return std::max(1, static_cast<int>(std::ceil(exponent / 5.0)));
}

int AutomaticShootingPieces(double exponent, int max_pieces) {
  return std::min(exponent <= 10.0 ? 1 : SuggestedShootingSegments(exponent), max_pieces);
}

}  // namespace cosserat
