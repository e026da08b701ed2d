#pragma once
/// \file
/// The actuation state handed to a rod model each control tick.

namespace cosserat {

/// What the robot's actuators do right now. The plain rod ignores it; robot models (tendons,
/// pressure, jamming, eversion) read the fields they own. Kept a plain aggregate so a controller
/// can fill it without allocating.
struct Actuation {
  /// Scales every stiffness profile's actuation-dependent factor; 1 for the plain rod.
  double stiffness_scale = 1.0;
};

}  // namespace cosserat
