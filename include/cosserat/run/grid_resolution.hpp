#pragma once
/// \file
/// How well an SE(3) static solve's grid resolves its shape. RK4 in s turns each section through
/// κ h per segment: a constant-curvature arc's tip is off by about 8e-3 (κ h)⁴ L in bending
/// (measured: 5.2e-4 L at κ h = 0.5, 8.1e-3 L at 1, 3.8e-2 L at 1.5; twist about the tangent moves
/// no point of a straight rod), and far beyond that the shot's frames leave rotation and its
/// positions run away (a pneumatic chamber at 1e9 Pa on a gel rod, κ h = 90: a "converged" tip
/// at 1e255 m, since no load asked anything of the shot).

#include <string>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/lie/types.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// What the nodes of a solved state say of the grid: the log lines, and whether the shot ran
/// away (a segment over 10 h long while the section turns by more than 1 rad on it: stretch
/// alone lengthens a segment legitimately).
struct GridResolution {
  bool ran_away = false;
  /// The bending turns a section by more than 1.5 rad on a segment: an arc's tip off by more
  /// than about 4 % of the length, and the loads' balance with it (status under_resolved).
  bool under_resolved = false;
  std::string log;  ///< the runaway's explanation, or the coarse-grid warning, or empty
};

/// From the nodes' s (m), positions (m) and curvatures [k1, k2, k3] (1/m, body frame) of a rod
/// of length L: the runaway check on the whole turn |κ| h, the warning (above 0.5 rad per
/// segment) on the bending part sqrt(k1² + k2²) h, with the error it implies and the nodes that
/// would keep it below 0.25.
GridResolution CheckGrid(const std::vector<double>& s, const std::vector<Vec3>& position,
                         const std::vector<Vec3>& curvature, double length);

/// The same for a converged SE(3) statics or modes result, from its nodes (for modes, the
/// equilibrium they are about): a runaway makes it non_finite, a grid under_resolved makes it
/// under_resolved (exit 1).
void CheckGridResolution(const io::Problem& problem, Result* result);

}  // namespace cosserat::run
