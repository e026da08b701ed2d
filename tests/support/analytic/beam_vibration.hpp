#pragma once
// Free vibration of uniform slender rods against which the dynamics and modal tests compare:
// Euler–Bernoulli bending (the roots β_n L of the frequency equations, computed here by
// bisection; the cantilever's mode shape; a cantilever carrying a tip mass; a cantilever under an
// axial compressive dead load) and the quarter-wave axial and torsional fundamentals.
//
// Sources: Rao, Vibration of Continuous Systems (2007), ch. 11 (Euler–Bernoulli beams: ω_n =
// (β_n L)² sqrt(E I / (ρ A L⁴)), clamped–free cos βL cosh βL = −1, free–free and clamped–clamped
// cos βL cosh βL = 1), ch. 8–9 (axial and torsional bars); Blevins, Formulas for Natural
// Frequency and Mode Shape (1979), table 8-1 (tip mass); Han, Benaroya & Wei (1999), J. Sound
// Vib. 225, 935–988 (the simply supported Timoshenko beam); Bokaian (1988), J. Sound Vib. 126,
// 49–65 (beams under compressive axial load; Galef's ω² ≈ ω₀² (1 − P/P_cr) is its
// approximation). tests/reference/natural_frequencies.json lists the same roots.

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// β_n L of the clamped–free (cantilever) beam, n = 1, 2, …: the n-th positive root of
/// cos x cosh x = −1 (Rao 2007), written cos x + 1/cosh x = 0; it lies in ((n − 1)π, nπ).
/// 1.8751040687…, 4.6940911329…, 7.8547574382…, 10.9955407348…
inline double CantileverBetaL(int n) {
  return Bisect([](double x) { return std::cos(x) + 1 / std::cosh(x); }, (n - 1) * kPi, n * kPi);
}

/// β_n L of the free–free beam (the same roots as clamped–clamped), n = 1, 2, … (the rigid-body
/// modes left out): the n-th positive root of cos x cosh x = 1, in (nπ, (n + 1)π).
/// 4.7300407448…, 7.8532046240…, 10.9956078380…
inline double FreeFreeBetaL(int n) {
  return Bisect([](double x) { return std::cos(x) - 1 / std::cosh(x); }, n * kPi, (n + 1) * kPi);
}

/// β_n L of the clamped–pinned beam, n = 1, 2, …: the n-th positive root of tan x = tanh x
/// (Rao 2007), written sin x cosh x − cos x sinh x = 0 over cosh x; it lies in (nπ, (n + ½)π).
/// 3.9266023120…, 7.0685827500…, 10.2101761242…
inline double ClampedPinnedVibrationBetaL(int n) {
  return Bisect([](double x) { return std::sin(x) - std::cos(x) * std::tanh(x); }, n * kPi,
                (n + 0.5) * kPi);
}

/// The n-th bending frequency (rad/s) of a simply supported Timoshenko beam (shear and rotary
/// inertia; Han, Benaroya & Wei 1999), the lower root ω² of
///   (j m / κGA) ω⁴ − (m + j k² + EI k² m / κGA) ω² + EI k⁴ = 0,   k = nπ/L,
/// with per-length mass m = ρA (kg/m), rotary inertia j = ρI (kg·m), bending stiffness EI (N·m²)
/// and shear stiffness κGA (N).
inline double SimplySupportedTimoshenkoOmega(int n, double EI, double kGA, double m, double j,
                                             double L) {
  const double k = n * kPi / L, k2 = k * k;
  const double a = j * m / kGA, b = m + j * k2 + EI * k2 * m / kGA, c = EI * k2 * k2;
  const double w2 = 2 * c / (b + std::sqrt(b * b - 4 * a * c));  // the lower root, stably
  return std::sqrt(w2);
}

/// Euler–Bernoulli bending frequency (rad/s) of a uniform beam, ω = (β L)² sqrt(E I/(ρ A L⁴)).
/// \param beta_L root of the frequency equation (–); EI (N·m²); rhoA mass per length (kg/m); L (m).
inline double EulerBernoulliOmega(double beta_L, double EI, double rhoA, double L) {
  return beta_L * beta_L * std::sqrt(EI / (rhoA * L * L * L * L));
}

/// The cantilever's n-th mode shape at x = s/L (clamp at 0, unnormalised, φ(0) = 0):
/// cosh βx − cos βx − σ (sinh βx − sin βx), σ = (cosh βL + cos βL)/(sinh βL + sin βL).
inline double CantileverModeShape(int n, double x) {
  const double b = CantileverBetaL(n);
  const double sigma = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
  return std::cosh(b * x) - std::cos(b * x) - sigma * (std::sinh(b * x) - std::sin(b * x));
}

/// The frequency equation of a cantilever carrying a tip point mass M (no rotary inertia) at
/// λ = βL, with mass_ratio = M / (ρ A L) (Blevins 1979, table 8-1):
/// 1 + cos λ cosh λ + (M / m_rod) λ (cos λ sinh λ − sin λ cosh λ). Positive below the first root.
inline double TipMassFrequencyEquation(double lambda, double mass_ratio) {
  return 1 + std::cos(lambda) * std::cosh(lambda) +
         mass_ratio * lambda *
             (std::cos(lambda) * std::sinh(lambda) - std::sin(lambda) * std::cosh(lambda));
}

/// Blevins (1979), table 8-1: λ₁ = 1.2479 for a tip mass equal to the beam's mass.
constexpr double kTipMassEqualBetaLPrinted = 1.2479;

/// First root λ = β₁L of TipMassFrequencyEquation, below the bare cantilever's 1.8751 (a mass
/// only lowers it); ω = λ² sqrt(E I/(ρ A L⁴)).
inline double CantileverTipMassBetaL(double mass_ratio) {
  return Bisect([=](double l) { return TipMassFrequencyEquation(l, mass_ratio); }, 0.0,
                CantileverBetaL(1));
}

/// Determinant of the boundary conditions of a cantilever under an axial compressive dead tip
/// load P at frequency w (rad/s): EI w'''' + P w'' − ρA ω² w = 0, w(0) = w'(0) = 0, w''(L) = 0,
/// EI w'''(L) + P w'(L) = 0, with w = a cosh αs + b sinh αs + c cos βs + d sin βs and α², −β² the
/// roots of EI r⁴ + P r² = ρA ω² (Bokaian 1988).
inline double CompressedCantileverDeterminant(double EI, double rhoA, double P, double L,
                                              double w) {
  const double disc = std::sqrt(P * P + 4 * EI * rhoA * w * w);
  const double a = std::sqrt((-P + disc) / (2 * EI)), b = std::sqrt((P + disc) / (2 * EI));
  const double ch = std::cosh(a * L), sh = std::sinh(a * L), c = std::cos(b * L),
               s = std::sin(b * L);
  Eigen::Matrix4d M;
  M << 1, 0, 1, 0,  //
      0, a, 0, b,   //
      a * a * ch, a * a * sh, -b * b * c, -b * b * s, EI * a * a * a * sh + P * a * sh,
      EI * a * a * a * ch + P * a * ch, EI * b * b * b * s - P * b * s,
      -EI * b * b * b * c + P * b * c;
  return M.determinant();
}

/// First bending frequency (rad/s) of the compressed cantilever: the first sign change of
/// CompressedCantileverDeterminant above 1e-3 w_hi, scanned in steps of 1 %, then bisected.
/// w_hi: an upper scale, e.g. the unloaded frequency.
inline double CompressedCantileverOmega(double EI, double rhoA, double P, double L, double w_hi) {
  double lo = 1e-3 * w_hi, hi = lo;
  const double d0 = CompressedCantileverDeterminant(EI, rhoA, P, L, lo);
  while (CompressedCantileverDeterminant(EI, rhoA, P, L, hi) * d0 > 0) hi *= 1.01;
  lo = hi / 1.01;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (CompressedCantileverDeterminant(EI, rhoA, P, L, mid) * d0 > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// n-th axial or torsional frequency (rad/s) of a clamped–free bar, a quarter-wave mode:
/// ω_n = (2n − 1) π c / (2L), with c = sqrt(E/ρ) (axial) or sqrt(G J/(ρ I_p)) (torsion; a circle
/// has J = I_p, so sqrt(G/ρ)) (Rao 2007, ch. 8–9).
inline double ClampedFreeWaveOmega(int n, double wave_speed, double L) {
  return (2 * n - 1) * kPi * wave_speed / (2 * L);
}

}  // namespace cosserat::truth
