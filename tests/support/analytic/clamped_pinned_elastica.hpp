#pragma once
// The planar, inextensible elastica of a clamped–pinned column whose pinned tip slides along
// the column's axis under a dead axial load P (the lateral reaction H at the pin is unknown).
// Dimensionless: EI = 1, L = 1. With θ the tangent's angle from the axis, x across it and z
// along it (the load along −z), the moment balance is θ'' = −(P sin θ + H cos θ), and
// x' = sin θ, z' = cos θ from the clamp θ(0) = 0, x(0) = z(0) = 0. The pin asks x(1) = 0 and
// θ'(1) = 0. Given the clamp's curvature θ'(0), Newton finds (P, H); the path, followed in
// θ'(0), shows the load rising from the Euler load 2.0457 π² to a peak and falling again.
//
// No closed form is used: the shot is RK4 on 4 000 steps (error ~ h⁴ ≈ 4e-15 of the unknowns)
// and the Jacobian central differences; the planar elastica is the truth the Cosserat column's
// shooting (3D, extensible, shearable) is compared with.

#include <array>
#include <cmath>

namespace cosserat::truth {

/// A state of the dimensionless clamped–pinned elastica.
struct ClampedPinnedElastica {
  double clamp_curvature = 0;  ///< θ'(0) (1/L)
  double load = 0;             ///< P (EI/L²)
  double pin_force = 0;        ///< H, across the axis (EI/L²)
  double tip_angle = 0;        ///< θ(1) (rad)
  double axial_tip = 1;        ///< z(1) (L)
  double largest_offset = 0;   ///< max |x| (L)
};

namespace clamped_pinned_detail {
/// Shoots from the clamp; returns [x(1), θ'(1)] and fills *out's shape fields.
inline std::array<double, 2> Shoot(double k0, double P, double H, ClampedPinnedElastica* out) {
  constexpr int kSteps = 4000;
  const double h = 1.0 / kSteps;
  using Y = std::array<double, 4>;  // θ, θ', x, z
  auto f = [&](const Y& y) {
    return Y{y[1], -(P * std::sin(y[0]) + H * std::cos(y[0])), std::sin(y[0]), std::cos(y[0])};
  };
  Y y{0, k0, 0, 0};
  double largest = 0;
  for (int i = 0; i < kSteps; ++i) {
    auto add = [](const Y& a, const Y& b, double c) {
      return Y{a[0] + c * b[0], a[1] + c * b[1], a[2] + c * b[2], a[3] + c * b[3]};
    };
    const Y a = f(y), b = f(add(y, a, h / 2)), c = f(add(y, b, h / 2)), d = f(add(y, c, h));
    for (int j = 0; j < 4; ++j) y[j] += h / 6 * (a[j] + 2 * b[j] + 2 * c[j] + d[j]);
    largest = std::max(largest, std::abs(y[2]));
  }
  if (out) {
    *out = {k0, P, H, y[0], y[3], largest};
  }
  return {y[2], y[1]};
}
}  // namespace clamped_pinned_detail

/// The equilibrium with clamp curvature k0, by Newton on (P, H) from the guess (P, H).
/// Returns false when Newton does not reach |residual| < 1e-12 in 50 iterations.
inline bool SolveClampedPinnedElastica(double k0, double P, double H, ClampedPinnedElastica* out) {
  using clamped_pinned_detail::Shoot;
  for (int it = 0; it < 50; ++it) {
    const std::array<double, 2> r = Shoot(k0, P, H, out);
    if (std::hypot(r[0], r[1]) < 1e-12) return true;
    const double e = 1e-6;
    const std::array<double, 2> rp = Shoot(k0, P + e, H, nullptr);
    const std::array<double, 2> rm = Shoot(k0, P - e, H, nullptr);
    const std::array<double, 2> hp = Shoot(k0, P, H + e, nullptr);
    const std::array<double, 2> hm = Shoot(k0, P, H - e, nullptr);
    const double a = (rp[0] - rm[0]) / (2 * e), b = (hp[0] - hm[0]) / (2 * e);
    const double c = (rp[1] - rm[1]) / (2 * e), d = (hp[1] - hm[1]) / (2 * e);
    const double det = a * d - b * c;
    if (!(std::abs(det) > 0)) return false;
    P -= (d * r[0] - b * r[1]) / det;
    H -= (a * r[1] - c * r[0]) / det;
  }
  return false;
}

/// The bowed equilibrium at load P (EI/L²) on the branch from the Euler load, below its peak:
/// followed in θ'(0) from the small bow until P is bracketed, then bisected. False past the peak.
inline bool ClampedPinnedElasticaAtLoad(double P, ClampedPinnedElastica* out) {
  const double euler = 2.0457 * M_PI * M_PI;
  ClampedPinnedElastica last, next;
  // Near the bifurcation the pin's force alone bends the clamp: θ'(0) = H L / EI.
  if (!SolveClampedPinnedElastica(0.5, euler, 0.5, &last)) return false;
  for (double k0 = 0.5; k0 < 12; k0 += 0.05) {
    if (!SolveClampedPinnedElastica(k0 + 0.05, last.load, last.pin_force, &next)) return false;
    if (next.load < last.load) return false;  // past the peak, below P
    if (next.load >= P) {
      double lo = last.clamp_curvature, hi = next.clamp_curvature;
      ClampedPinnedElastica mid = last;
      for (int i = 0; i < 60; ++i) {
        if (!SolveClampedPinnedElastica(0.5 * (lo + hi), mid.load, mid.pin_force, &mid))
          return false;
        (mid.load < P ? lo : hi) = mid.clamp_curvature;
      }
      *out = mid;
      return true;
    }
    last = next;
  }
  return false;
}

/// The peak of the bowed branch: the largest P (EI/L²) a bowed clamped–pinned column holds,
/// by golden-section search on θ'(0) about the marched maximum.
inline ClampedPinnedElastica ClampedPinnedElasticaPeak() {
  const double euler = 2.0457 * M_PI * M_PI;
  ClampedPinnedElastica last, best;
  SolveClampedPinnedElastica(0.5, euler, 0.5, &last);  // as in ClampedPinnedElasticaAtLoad
  best = last;
  for (double k0 = 0.55; k0 < 12; k0 += 0.05) {
    if (!SolveClampedPinnedElastica(k0, last.load, last.pin_force, &last)) break;
    if (last.load > best.load) best = last;
  }
  double lo = best.clamp_curvature - 0.05, hi = best.clamp_curvature + 0.05;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  ClampedPinnedElastica a, b;
  for (int i = 0; i < 60; ++i) {
    SolveClampedPinnedElastica(hi - g * (hi - lo), best.load, best.pin_force, &a);
    SolveClampedPinnedElastica(lo + g * (hi - lo), best.load, best.pin_force, &b);
    (a.load > b.load ? hi : lo) = a.load > b.load ? b.clamp_curvature : a.clamp_curvature;
  }
  SolveClampedPinnedElastica(0.5 * (lo + hi), best.load, best.pin_force, &best);
  return best;
}

}  // namespace cosserat::truth
