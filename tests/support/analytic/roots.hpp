#pragma once
// π, and bisection for the transcendental equations of the analytic references in this folder,
// so that their roots (β_n L, the clamped–pinned buckling root, Greenhill's load…) are computed,
// not typed. Test support: header-only, no state.

#include <cmath>

namespace cosserat::truth {

/// A root of f in [lo, hi], where f(lo) and f(hi) have opposite signs (f(lo) ≠ 0), by bisection
/// until the bracket is one unit in the last place wide (at most 200 halvings).
template <typename F>
double Bisect(F f, double lo, double hi) {
  const bool lo_positive = f(lo) > 0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // the bracket holds two neighbouring doubles
    ((f(mid) > 0) == lo_positive ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace cosserat::truth
