#pragma once
/// \file
/// Pressurised chambers of a soft pneumatic or hydraulic actuator (Polygerinos et al. 2015): a
/// channel parallel to the centreline over s ∈ [start, end), at the offset r = [x, y] in the
/// section (body frame, m), of cross-section area A (m², in the section plane). What its gauge
/// pressure does to the rod is the chamber law (constitutive/chamber_law.hpp); the pressures are
/// part of the Actuation (Actuation::chamber_pressure), in the order of the rod's chamber list.

#include <string>

#include "cosserat/lie/types.hpp"

namespace cosserat {

struct Chamber {
  std::string name;
  Vec2 offset = Vec2::Zero();  ///< r, body frame, m: where the chamber's centroid sits
  double area = 0.0;           ///< A, m², the chamber's cross-section in the section plane
  double start = 0.0;          ///< s0, m
  double end = 0.0;            ///< s1, m (> s0)

  /// True for s in [start, end): the chamber's interval, closed at its base end like a band.
  bool Covers(double s) const { return s >= start && s < end; }
  /// Radius of the disc of area A, m: how far the chamber's wall reaches from its centroid when
  /// it is round.
  double EquivalentRadius() const;
  /// Finite offset, A > 0, 0 <= start < end <= length; else writes why.
  bool IsValid(double length, std::string* why) const;
};

}  // namespace cosserat
