#pragma once
// Critical loads of straight elastic columns against which the buckling tests compare: Euler's
// loads for the four end conditions, their mode shapes, the first-order correction of a shearable
// and extensible column (Engesser's shear term and the axial shortening), and Greenhill's
// standing column under its own weight.
//
// Sources: Euler (1744); Timoshenko & Gere, Theory of Elastic Stability (1961), ch. 2: the end
// conditions (clamped–pinned: tan βL = βL, βL = 4.4934), the effect of the shearing force
// (Engesser 1891: P_cr = P_E / (1 + P_E/(κGA))) and buckling under a distributed axial load
// (Greenhill 1881: q L³/EI = 7.837, the first root of J_{−1/3}(2/3 sqrt(q L³/EI)) = 0).
// tests/reference/stability_and_moment.json lists the same formulas.

#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// The printed values the functions below are checked against (test_analytic_references.cpp):
/// clamped–pinned βL and P_cr L²/EI (Timoshenko & Gere 1961; stability_and_moment.json), and
/// Greenhill's q L³/EI (Timoshenko & Gere 1961).
constexpr double kClampedPinnedBetaLPrinted = 4.4934;
constexpr double kClampedPinnedLoadPrinted = 20.19;
constexpr double kGreenhillLoadPrinted = 7.8373;

/// βL = 4.4934094579… of the clamped–pinned column, the first positive root of tan x = x (written
/// sin x − x cos x = 0, in (π, 3π/2)).
inline double ClampedPinnedBetaL() {
  return Bisect([](double x) { return std::sin(x) - x * std::cos(x); }, kPi, 1.5 * kPi);
}

/// k-th Euler load (N) of a cantilever (clamped at s = 0, free at L), k = 1, 2, …:
/// (2k − 1)² π² E I / (4 L²). \param EI bending stiffness (N·m²); L length (m).
inline double EulerLoadClampedFree(double EI, double L, int k = 1) {
  return (2 * k - 1) * (2 * k - 1) * kPi * kPi * EI / (4 * L * L);
}
/// Euler load (N) of the pinned–pinned column, π² E I / L².
inline double EulerLoadPinnedPinned(double EI, double L) { return kPi * kPi * EI / (L * L); }
/// Euler load (N) of the clamped–clamped column, 4 π² E I / L².
inline double EulerLoadClampedClamped(double EI, double L) { return 4 * kPi * kPi * EI / (L * L); }
/// Euler load (N) of the clamped–pinned column, (4.4934 / L)² E I ≈ 20.19 E I / L².
inline double EulerLoadClampedPinned(double EI, double L) {
  const double b = ClampedPinnedBetaL();
  return b * b * EI / (L * L);
}

/// Euler's first buckling mode of the cantilever, lateral displacement at x = s/L, unit at the
/// tip: 1 − cos(πx/2).
inline double EulerModeClampedFree(double x) { return 1 - std::cos(kPi * x / 2); }
/// Euler's first buckling mode of the pinned–pinned column, unit at mid-span: sin(πx).
inline double EulerModePinnedPinned(double x) { return std::sin(kPi * x); }

/// First-order relative change of the critical load, P_cr/P_E − 1, of a column that shears and
/// stretches: shear lowers it by P_E/(κGA) (Engesser 1891) and the
/// axial shortening raises it by P_E/(EA). For a circle (I/A = r²/4):
/// (π² c² r²/(4 L²)) (1 − E/(κG)) with P_E = c² π² EI/L².
/// \param P_E Euler load (N); EA axial stiffness (N); kGA shear stiffness κGA (N).
inline double ShearAndShorteningShift(double P_E, double EA, double kGA) {
  return P_E / EA - P_E / kGA;
}

/// Greenhill's standing column (clamped at the foot, free at the top) under its own weight q per
/// length buckles at q L³/E I = (3 j/2)², j the first zero of J_{−1/3}: 7.8373…. J_{−1/3} by its
/// power series (Σ (−1)^m (x/2)^{2m−1/3} / (m! Γ(m + 2/3)), converged far below 1e-15 at x < 3).
inline double GreenhillSelfWeightLoad() {
  auto j = [](double x) {
    double sum = 0;
    for (int m = 0; m < 40; ++m)
      sum += std::pow(-1.0, m) * std::pow(x / 2, 2 * m - 1.0 / 3) /
             (std::tgamma(m + 1.0) * std::tgamma(m + 2.0 / 3));
    return sum;
  };
  const double zero = Bisect(j, 1.0, 3.0);
  return 2.25 * zero * zero;
}

}  // namespace cosserat::truth
