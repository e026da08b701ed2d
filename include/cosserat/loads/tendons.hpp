#pragma once
/// \file
/// Tendons routed through a rod (Rucker & Webster 2011). A tendon runs from an actuator at the
/// base through guides at the offset r(s) = [x(s), y(s), 0] in the section (body frame, m) and
/// is anchored at the tip. With tension τ its unit tangent, body frame, is
///   t = q / |q|,  q = Γ + K × r + r'        (the body-frame derivative of p + R r, over R),
/// and the pair "rod + tendon" carries the total internal wrench
///   W = K (ξ − ξ*) + Σ τ_i a_i(ξ),  a_i = [r_i × t_i; t_i],
/// which obeys the balance laws of the plain rod. This is Rucker & Webster's model with its
/// distributed load and its terminal load at the anchor already summed into W: the solvers keep
/// their balance equations and only the constitutive law changes (solved for ξ per stage).

#include <array>
#include <string>
#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/rod/actuation.hpp"

namespace cosserat {

/// Where a tendon runs in the section, as a function of s. Allocation-free to evaluate.
struct TendonRoute {
  enum class Kind {
    kLinear,   ///< r(s) = r0 + (s / L)(r1 − r0): parallel (r1 = r0) or converging/diverging
    kHelical,  ///< r(s) = ρ [cos φ(s), sin φ(s)], φ(s) = φ0 + 2π s / pitch
  };
  Kind kind = Kind::kLinear;
  Vec2 offset_base = Vec2::Zero();  ///< linear: r(0), m
  Vec2 offset_tip = Vec2::Zero();   ///< linear: r(L), m
  double radius = 0.0;              ///< helical: ρ, m
  double pitch = 0.0;  ///< helical: arc length per turn, m; > 0 turns anticlockwise about body z
  double phase = 0.0;  ///< helical: φ0, rad

  static TendonRoute Parallel(const Vec2& offset);
  static TendonRoute Converging(const Vec2& offset_base, const Vec2& offset_tip);
  static TendonRoute Helical(double radius, double pitch, double phase);

  /// r(s) in the body frame (z = 0), m, for a rod of length L.
  Vec3 OffsetAt(double s, double length) const;
  /// dr/ds, body frame.
  Vec3 OffsetRateAt(double s, double length) const;
  /// Largest |r(s)| over the rod, m.
  double MaxOffset() const;
  bool IsValid(std::string* why) const;
};

struct Tendon {
  std::string name;
  TendonRoute route;
};

/// The tendons' offsets at one point s, sampled once per solver (routes do not change).
struct TendonSample {
  int count = 0;
  std::array<Vec3, Actuation::kMaxTendons> offset{};       ///< r_i(s), body frame, m
  std::array<Vec3, Actuation::kMaxTendons> offset_rate{};  ///< r_i'(s)
};

TendonSample SampleTendons(const std::vector<Tendon>& tendons, double s, double length);

/// Σ τ_i a_i(ξ) (body frame, [N·m; N]) and, if asked, its derivative in ξ (6 × 6) and the
/// columns a_i (derivative in τ_i).
Vec6 TendonWrench(const TendonSample& sample, const double* tension, const Vec6& xi,
                  Mat6* d_xi = nullptr, std::array<Vec6, Actuation::kMaxTendons>* a = nullptr);

/// Solves K (ξ − ξ*) + Σ τ_i a_i(ξ) = W for the strain ξ by simplified Newton from `xi` (in: a
/// guess, out: the strain, to 1e-12 relative). If H is given, writes H = K + ∂(Σ τ a)/∂ξ at the
/// solution, so dξ = H⁻¹ dW. Returns
/// false if it did not converge to round-off within 12 iterations (a tendon path folded back,
/// |q| → 0).
bool SolveTendonStrain(const Mat6& stiffness, const Vec6& rest_strain, const TendonSample& sample,
                       const double* tension, const Vec6& W, Vec6* xi, Mat6* H);

/// |q_i| = |Γ + K × r_i + r_i'|: the stretch of tendon i's path per unit arc length of the rod.
double TendonPathRate(const TendonSample& sample, int i, const Vec6& xi);

}  // namespace cosserat
