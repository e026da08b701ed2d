#pragma once
// Cables between two supports: the elastic catenary and the linear vibration of a sagging cable.
// Sources: Irvine, Cable Structures (1981), ch. 2 (the elastic catenary) and ch. 3 (free
// vibrations; Irvine & Caughey 1974 for the in-plane symmetric modes).

#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// An elastic catenary hanging between A (s = 0) and B (s = L₀, unstretched arc length) in a
/// vertical plane: B lies l further along the horizontal and h higher. Its weight is w per
/// unstretched length (N/m), its axial stiffness EA (N). H is the horizontal force and V the
/// upward force the support at A exerts (N); the tension at s is sqrt(H² + (V − w s)²).
struct ElasticCatenary {
  double H = 0, V = 0;
  double w = 0, EA = 0, L0 = 0;
  /// Position of s relative to A: horizontal x(s) and vertical z(s) (m).
  double X(double s) const {
    return H * s / EA + H / w * (std::asinh((w * s - V) / H) + std::asinh(V / H));
  }
  double Z(double s) const {
    return (w * s * s / 2 - V * s) / EA +
           (std::hypot(H, w * s - V) - std::hypot(H, V)) / w;
  }
  double Tension(double s) const { return std::hypot(H, V - w * s); }
};

/// Solves x(L₀) = l, z(L₀) = h for H > 0 and V by Newton on the two end equations (central
/// differences for the 2×2 Jacobian), from the parabolic estimate. Converges to ~1e-13 relative
/// for sags from taut to deep.
inline ElasticCatenary SolveElasticCatenary(double l, double h, double L0, double w, double EA) {
  ElasticCatenary c;
  c.w = w;
  c.EA = EA;
  c.L0 = L0;
  // Start: the parabolic cable of the same chord with sag from the length excess (taut: a
  // tension of a tenth of the weight's).
  const double chord = std::hypot(l, h), excess = std::max(L0 - chord, 1e-3 * chord);
  const double sag = std::sqrt(3.0 * chord * excess / 8.0);
  c.H = std::max(w * l * l / (8 * sag), 0.1 * w * L0);
  c.V = w * L0 / 2 + c.H * h / l;
  for (int it = 0; it < 100; ++it) {
    const double fx = c.X(L0) - l, fz = c.Z(L0) - h;
    if (std::abs(fx) + std::abs(fz) < 1e-14 * (l + std::abs(h))) break;
    const double dH = 1e-7 * c.H, dV = 1e-7 * std::max(std::abs(c.V), c.H);
    ElasticCatenary a = c, b = c;
    a.H += dH;
    b.V += dV;
    const double xH = (a.X(L0) - c.X(L0)) / dH, zH = (a.Z(L0) - c.Z(L0)) / dH;
    const double xV = (b.X(L0) - c.X(L0)) / dV, zV = (b.Z(L0) - c.Z(L0)) / dV;
    const double det = xH * zV - xV * zH;
    double stepH = (fx * zV - xV * fz) / det, stepV = (xH * fz - fx * zH) / det;
    const double limit = 0.5 * c.H / std::max(std::abs(stepH), 1e-300);
    if (limit < 1) stepH *= limit, stepV *= limit;  // keep H > 0
    c.H -= stepH;
    c.V -= stepV;
  }
  return c;
}

/// A line from an anchor on a frictionless sea bed to a fairlead X along the bed and h above it:
/// it lies on the bed up to the touchdown point and hangs as an elastic catenary from there, with
/// zero slope (and the horizontal tension H) at touchdown. Unknowns H and the suspended
/// (unstretched) length Ls; the grounded part stretches by H/EA.
struct GroundedCatenary {
  double H = 0, suspended = 0;  ///< N, m (unstretched)
  double touchdown_x = 0;       ///< the touchdown point's distance from the anchor, m
};

inline GroundedCatenary SolveGroundedCatenary(double X, double h, double L0, double w, double EA) {
  // The hanging part from touchdown (s = 0, V = 0) to the fairlead (s = Ls).
  const auto x_of = [&](double H, double Ls) {
    return H / w * std::asinh(w * Ls / H) + H * Ls / EA + (L0 - Ls) * (1 + H / EA);
  };
  const auto z_of = [&](double H, double Ls) {
    return H / w * (std::hypot(1.0, w * Ls / H) - 1) + w * Ls * Ls / (2 * EA);
  };
  GroundedCatenary g;
  g.suspended = std::min(L0, 1.5 * h);
  g.H = w * h;
  for (int it = 0; it < 200; ++it) {
    const double fx = x_of(g.H, g.suspended) - X, fz = z_of(g.H, g.suspended) - h;
    if (std::abs(fx) + std::abs(fz) < 1e-13 * (X + h)) break;
    const double dH = 1e-7 * g.H, dL = 1e-7 * g.suspended;
    const double xH = (x_of(g.H + dH, g.suspended) - x_of(g.H, g.suspended)) / dH;
    const double zH = (z_of(g.H + dH, g.suspended) - z_of(g.H, g.suspended)) / dH;
    const double xL = (x_of(g.H, g.suspended + dL) - x_of(g.H, g.suspended)) / dL;
    const double zL = (z_of(g.H, g.suspended + dL) - z_of(g.H, g.suspended)) / dL;
    const double det = xH * zL - xL * zH;
    double sH = (fx * zL - xL * fz) / det, sL = (xH * fz - fx * zH) / det;
    const double damp = std::min({1.0, 0.5 * g.H / std::max(std::abs(sH), 1e-300),
                                  0.5 * g.suspended / std::max(std::abs(sL), 1e-300)});
    g.H -= damp * sH;
    g.suspended -= damp * sL;
  }
  g.touchdown_x = (L0 - g.suspended) * (1 + g.H / EA);
  return g;
}

/// Out-of-plane (and antisymmetric in-plane) frequencies of a shallow cable of span l: those of
/// a taut string, ω_n = (nπ/l) sqrt(H/m), m the mass per unit length (rad/s).
inline double TautStringOmega(int n, double H, double m, double l) {
  return n * M_PI / l * std::sqrt(H / m);
}

/// Irvine's parameter λ² = (m g l / H)² l / (H L_e / EA) of a shallow cable, with
/// L_e = l (1 + 8 (d/l)²) for the mid-span sag d.
inline double IrvineLambdaSquared(double m, double g, double l, double H, double EA, double sag) {
  const double Le = l * (1 + 8 * (sag / l) * (sag / l));
  const double r = m * g * l / H;
  return r * r * l / (H * Le / EA);
}

/// The first symmetric in-plane frequency (rad/s) of a shallow cable, from
/// tan(ω̄/2) = ω̄/2 − (4/λ²)(ω̄/2)³, ω̄ = ω l / sqrt(H/m): the root between π/2 and 3π/2 (below
/// the crossover λ² = 4π² it lies under 2π, above it over). The root of
/// g(x) = sin x − cos x (x − 4 x³/λ²) is bracketed in (π/2, 3π/2) and bisected.
inline double IrvineFirstSymmetricOmega(double lambda2, double H, double m, double l) {
  const auto g = [&](double x) { return std::sin(x) - std::cos(x) * (x - 4 * x * x * x / lambda2); };
  const double x = Bisect(g, 0.5 * M_PI + 1e-12, 1.5 * M_PI - 1e-12);
  return 2 * x / l * std::sqrt(H / m);
}

}  // namespace cosserat::truth
