#pragma once
/// \file
/// Tendons routed through a rod (Rucker & Webster 2011): where each runs in the section, as a
/// function of s. A tendon runs from an actuator at the base through guides at the offset
/// r(s) = [x(s), y(s), 0] in the section (body frame, m) and is anchored at the tip. What a
/// tension does to the rod is the tendon-augmented constitutive law
/// (constitutive/tendon_law.hpp).

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
  /// Where it is anchored, m of s: 0 for the tip; else inside the rod (a multi-segment robot's
  /// tendons end at their segment's end, passing through the segments before it). Beyond its
  /// anchor the tendon carries nothing; the grid puts a node there (RodModel::Breakpoints).
  double anchor = 0.0;
};

/// The tendons' offsets at one point s, sampled once per solver (routes do not change).
struct TendonSample {
  int count = 0;
  std::array<Vec3, Actuation::kMaxTendons> offset{};       ///< r_i(s), body frame, m
  std::array<Vec3, Actuation::kMaxTendons> offset_rate{};  ///< r_i'(s)
  std::array<bool, Actuation::kMaxTendons> ended{};        ///< s at or past tendon i's anchor
};

TendonSample SampleTendons(const std::vector<Tendon>& tendons, double s, double length);

}  // namespace cosserat
