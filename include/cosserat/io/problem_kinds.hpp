#pragma once
/// \file
/// The named choices of a problem file (docs/problem-format.md) as enums: each is parsed once,
/// by the problem parser, and written back with ToString, which gives the file's own name.

#include <string>
#include <vector>

namespace cosserat::io {

/// "analysis".
enum class Analysis { kStatics, kDynamics, kBuckling, kModes };

/// "formulation": the SE(3) strong form with shooting, or Lang & Linn's quaternion finite
/// differences.
enum class Formulation { kSe3Shooting, kQuaternionFd };

/// "boundary": the end conditions. A cantilever is clamped at s = 0 and free at s = L; the column
/// ends guide the tip along the base's axis (docs/buckling.md).
enum class Boundary {
  kCantilever,
  kFreeFree,
  kPinnedPinned,
  kClampedClamped,
  kClampedPinned,
  kAnchored,  ///< both ends held at given points ("anchor"): cables, risers, moorings
};

/// "dynamics.spatial_scheme": the explicit Runge–Kutta scheme of the dynamic shot in s (RK4,
/// order 4; Heun, order 2; RK4 across pairs of segments, order 4 at Heun's cost).
enum class ShotScheme { kRk4, kHeun, kRk4Pairs };

/// "robot.kind"; kNone when the problem has no "robot".
enum class RobotKind { kNone, kTendon, kJamming, kEversion, kPneumatic };

/// "buckling.load": the load path searched.
enum class BucklingLoad {
  kTipForce,
  kTipMoment,
  kGravity,
  kDistributedForce,
  kTendonTension,
  kPressure,
};

/// The names a problem file gives each value, in the enum's order ("none", RobotKind::kNone, is
/// never read from a file).
template <typename Enum>
const std::vector<std::string>& Names();
template <>
const std::vector<std::string>& Names<Analysis>();
template <>
const std::vector<std::string>& Names<Formulation>();
template <>
const std::vector<std::string>& Names<Boundary>();
template <>
const std::vector<std::string>& Names<ShotScheme>();
template <>
const std::vector<std::string>& Names<RobotKind>();
template <>
const std::vector<std::string>& Names<BucklingLoad>();

/// The file's name of a value, e.g. "quaternion-fd".
const std::string& ToString(Analysis value);
const std::string& ToString(Formulation value);
const std::string& ToString(Boundary value);
const std::string& ToString(ShotScheme value);
const std::string& ToString(RobotKind value);
const std::string& ToString(BucklingLoad value);

/// The value a file names; false (and *value unchanged) for a name that is none of Names<Enum>().
template <typename Enum>
bool FromString(const std::string& name, Enum* value) {
  const std::vector<std::string>& names = Names<Enum>();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) {
      *value = static_cast<Enum>(i);
      return true;
    }
  }
  return false;
}

}  // namespace cosserat::io
