#pragma once
/// \file
/// The actuation state handed to a rod model each control tick.

#include <array>
#include <string>

namespace cosserat {

/// What the robot's actuators do right now. The plain rod ignores it; robot models (tendons,
/// pressure, jamming, eversion) read the fields they own. A plain fixed-size aggregate, so a
/// controller can fill it every tick without allocating.
struct Actuation {
  static constexpr int kMaxTendons = 8;
  static constexpr int kMaxSegments = 16;
  static constexpr int kMaxChambers = 16;

  /// A stiffness command for section profiles written in C++ that read it (a heated or
  /// electro-adhesive section whose stiffness a controller sets); none of the built-in profiles
  /// reads it. The stepper re-samples the sections when it changes. 1 by default.
  double stiffness_scale = 1.0;
  /// Internal (inflation) gauge pressure of an inflated body, Pa. Read by pressure-dependent
  /// profiles (E_eff(p)) and by eversion robots (follower tip force p·A).
  double pressure = 0.0;
  /// Tendon tensions, N (≥ 0), in the order of the robot's tendon list.
  std::array<double, kMaxTendons> tendon_tension{};
  /// Gauge pressure of each pressurised chamber (rod/chamber.hpp), Pa, in the order of the rod's
  /// chamber list; > 0 inflates (extends the rod and bends it away from the chamber), < 0 is a
  /// partial vacuum (down to −101 325 Pa, absolute vacuum at sea level).
  std::array<double, kMaxChambers> chamber_pressure{};
  /// Layer-jamming pressure difference ΔP of each switchable segment, Pa; 0: compliant.
  std::array<double, kMaxSegments> jamming_pressure{};

  /// The rules every actuation obeys (the problem file's and the Python module's): finite
  /// values, pressure and jamming pressures >= 0 (Pa), stiffness_scale > 0, tensions >= 0 (N;
  /// a tendon cannot push), chamber pressures >= −101 325 Pa, and no tension on a tendon past the
  /// first `tendon_count` (the rod's) and no pressure in a chamber past the first
  /// `chamber_count`. On failure `why` (if given) names the field: "<field>: expected ...".
  bool IsValid(std::string* why, int tendon_count = kMaxTendons,
               int chamber_count = kMaxChambers) const;

  /// Every value finite (no NaN or Inf).
  bool AllFinite() const;

  /// Every field equal (the same command).
  bool operator==(const Actuation& o) const {
    return stiffness_scale == o.stiffness_scale && pressure == o.pressure &&
           tendon_tension == o.tendon_tension && chamber_pressure == o.chamber_pressure &&
           jamming_pressure == o.jamming_pressure;
  }
  bool operator!=(const Actuation& o) const { return !(*this == o); }

  /// For the solvers' setters: throws std::invalid_argument naming the field ("actuation.<field>:
  /// expected ...") when IsValid refuses the actuation for a rod of these tendons and chambers.
  void Require(int tendon_count, int chamber_count) const;

  /// Absolute vacuum as a gauge pressure, Pa: the lowest chamber pressure.
  static constexpr double kVacuumGaugePressure = -101325.0;
};

}  // namespace cosserat
