#include "frequency_shot_limit.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "cosserat/constitutive/section_law.hpp"

namespace cosserat::detail {
namespace {

/// What ∫ μ ds reads at each node of the equilibrium: s (m), the least EI (N·m²), ρA (kg/m) and
/// the axial force T (N), sampled once for every ω.
struct ShotProfile {
  std::vector<double> s, ei, rho_a, tension;

  ShotProfile(const RodModel& rod, const Actuation& actuation, const RodState& equilibrium) {
    if (!rod.section) return;
    for (int i = 0; i < equilibrium.size(); ++i) {
      const SectionProperties p = rod.section->At(equilibrium.s[i], actuation);
      s.push_back(equilibrium.s[i]);
      ei.push_back(p.min_bending_stiffness());
      rho_a.push_back(p.mass(3, 3));
      tension.push_back(equilibrium.wrench_B[i](5));
    }
  }

  double Exponent(double omega) const {
    auto mu = [&](size_t i) {  // 1/m
      if (!(ei[i] > 0.0)) return 0.0;
      const double T = tension[i];
      return std::sqrt((T + std::sqrt(T * T + 4.0 * ei[i] * rho_a[i] * omega * omega)) /
                       (2.0 * ei[i]));
    };
    double sum = 0.0;
    for (size_t i = 1; i < s.size(); ++i) sum += 0.5 * (mu(i - 1) + mu(i)) * (s[i] - s[i - 1]);
    return sum;
  }
};

}  // namespace

double FrequencyShotLimit(const RodModel& rod, const Actuation& actuation,
                          const RodState& equilibrium) {
  const ShotProfile profile(rod, actuation, equilibrium);
  auto exponent = [&](double w) { return profile.Exponent(w); };
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
