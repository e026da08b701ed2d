#pragma once
/// \file
/// The envelope of a dynamics run's section forces over its recorded frames: at every node the
/// largest and smallest axial force (tension positive) and the largest bending moment — what a
/// riser's or a cable's design checks take from a time history.

#include <vector>

#include "cosserat/state/rod_state.hpp"

namespace cosserat::io {

struct LoadEnvelope {
  std::vector<double> tension_max;  ///< max over frames of n₃, the body-frame axial force, N
  std::vector<double> tension_min;  ///< min over frames of n₃, N (negative: compression)
  std::vector<double> moment_max;   ///< max over frames of sqrt(m₁² + m₂²), N·m
  int frames = 0;

  /// Takes one frame's state (the node count must not change between frames).
  void Add(const RodState& state);
};

}  // namespace cosserat::io
