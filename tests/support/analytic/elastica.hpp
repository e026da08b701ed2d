#pragma once
// The inextensible, unshearable elastica: the large-deflection cantilever under a dead tip load
// perpendicular to its axis, and the post-buckled cantilever column under an axial dead load.
//
// Sources: Bisshopp & Drucker (1945), Quarterly of Applied Mathematics 3, 272–275 (tip load;
// tests/reference/elastica_tip_load.json tabulates it); Timoshenko & Gere, Theory of Elastic
// Stability (1961), §2.7 (the post-buckled cantilever, with its table for a tip angle of 60°).

#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// Incomplete elliptic integral of the first (F(φ, k)) or second (E(φ, k)) kind, k < 1, by
/// composite Simpson on 20 000 intervals (smooth integrand: error ~ (φ/n)⁴, far below 1e-12).
inline double EllipticIntegral(double phi, double k, bool second_kind) {
  auto f = [&](double t) {
    const double d = std::sqrt(1 - k * k * std::sin(t) * std::sin(t));
    return second_kind ? d : 1 / d;
  };
  const int n = 20000;
  double sum = f(0) + f(phi);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(phi * i / n);
  return sum * phi / (3 * n);
}

/// Complete elliptic integrals K(k) and E(k), k < 1, by the arithmetic–geometric mean.
inline void CompleteEllipticKE(double k, double* K, double* E) {
  double a = 1, b = std::sqrt(1 - k * k), sum = k * k / 2, pow2 = 0.5;
  for (int i = 0; i < 30; ++i) {
    const double c = 0.5 * (a - b);
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
    pow2 *= 2;
    sum += pow2 * c * c;
  }
  *K = kPi / (2 * a);
  *E = *K * (1 - sum);
}

/// Tip deflection / L, along the load, of the cantilever elastica under a dead end load P
/// perpendicular to the undeformed axis, α = P L²/(E I) (Bisshopp & Drucker 1945): with
/// k² = (1 + sin θ₀)/2 and φ₁ = asin(1/(k√2)), sqrt(α) = F(k) − F(φ₁, k) fixes the tip angle θ₀
/// (bisection), and deflection/L = 1 − 2 (E(k) − E(φ₁, k))/sqrt(α).
inline double TipLoadElasticaDeflection(double alpha) {
  auto parts = [&](double theta0, double* k, double* phi1) {
    *k = std::sqrt((1 + std::sin(theta0)) / 2);
    *phi1 = std::asin(1 / (*k * std::sqrt(2.0)));
  };
  double lo = 1e-9, hi = kPi / 2 - 1e-12;
  for (int it = 0; it < 100; ++it) {  // sqrt(alpha) = F(k) − F(φ1, k) grows with θ0
    const double mid = 0.5 * (lo + hi);
    double k, phi1;
    parts(mid, &k, &phi1);
    const double g = EllipticIntegral(kPi / 2, k, false) - EllipticIntegral(phi1, k, false);
    (g < std::sqrt(alpha) ? lo : hi) = mid;
  }
  double k, phi1;
  parts(0.5 * (lo + hi), &k, &phi1);
  return 1 - 2 * (EllipticIntegral(kPi / 2, k, true) - EllipticIntegral(phi1, k, true)) /
                 std::sqrt(alpha);
}

/// The post-buckled cantilever column: load over its Euler load, tip angle from the axis (rad),
/// tip deflection and tip position along the axis, both over L.
struct PostBuckledCantilever {
  double load_ratio, angle, deflection, axial;
};

/// The post-buckled cantilever with tip angle α = 2 asin k (Timoshenko & Gere 1961, §2.7):
/// P/P_cr = (2 K(k)/π)², deflection/L = 2k / K(k), axial/L = 2 E(k)/K(k) − 1.
inline PostBuckledCantilever PostBuckledCantileverAtModulus(double k) {
  double K, E;
  CompleteEllipticKE(k, &K, &E);
  return {std::pow(2 * K / kPi, 2), 2 * std::asin(k), 2 * k / K, 2 * E / K - 1};
}

/// Timoshenko & Gere (1961), §2.7, table for a tip angle of 60° (k = sin 30° = 1/2), as printed:
/// P/P_cr, deflection/L and axial/L.
constexpr PostBuckledCantilever kPostBuckled60DegreesPrinted = {1.152, 60 * kPi / 180, 0.593,
                                                                0.741};

/// The same at a given load ratio P/P_cr ≥ 1 (bisection on k in [0, 1 − 1e-12]: ratios up to
/// about 89, a tip angle within 2e-4° of 180°).
inline PostBuckledCantilever PostBuckledCantileverAtLoad(double ratio) {
  double lo = 0, hi = 1 - 1e-12;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (PostBuckledCantileverAtModulus(mid).load_ratio < ratio ? lo : hi) = mid;
  }
  return PostBuckledCantileverAtModulus(0.5 * (lo + hi));
}

/// Slope of the post-buckled branch at the bifurcation: deflection/L ≈ (4√2/π) sqrt(P/P_cr − 1)
/// as P → P_cr (the expansion of PostBuckledCantileverAtModulus for small k).
inline double PostBuckledDeflectionSlope() { return 4 * std::sqrt(2.0) / kPi; }

}  // namespace cosserat::truth
