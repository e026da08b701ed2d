#include "frequency_shot_limit.hpp"

#include <cmath>
#include <limits>

#include "cosserat/constitutive/section_law.hpp"

namespace cosserat::detail {

double FrequencyShotExponent(const RodModel& rod, const Actuation& actuation,
                             const RodState& equilibrium, double omega) {
  const int n = equilibrium.size();
  if (n < 2 || !rod.section) return 0.0;
  auto mu = [&](int i) {  // 1/m
    const SectionProperties p = rod.section->At(equilibrium.s[i], actuation);
    const double EI = p.min_bending_stiffness(), rhoA = p.mass(3, 3);
    if (!(EI > 0.0)) return 0.0;
    const double T = equilibrium.wrench_B[i](5);
    return std::sqrt((T + std::sqrt(T * T + 4.0 * EI * rhoA * omega * omega)) / (2.0 * EI));
  };
  double sum = 0.0, last = mu(0);
  for (int i = 1; i < n; ++i) {
    const double here = mu(i);
    sum += 0.5 * (last + here) * (equilibrium.s[i] - equilibrium.s[i - 1]);
    last = here;
  }
  return sum;
}

double FrequencyShotLimit(const RodModel& rod, const Actuation& actuation,
                          const RodState& equilibrium) {
  auto exponent = [&](double w) { return FrequencyShotExponent(rod, actuation, equilibrium, w); };
  if (exponent(0.0) >= kMaxFrequencyShotExponent) return 0.0;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; exponent(hi) < kMaxFrequencyShotExponent; ++i, lo = hi, hi *= 4.0)
    if (i == 200) return std::numeric_limits<double>::infinity();
  for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (exponent(mid) < kMaxFrequencyShotExponent ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace cosserat::detail
