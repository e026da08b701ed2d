#pragma once
/// \file
/// How well a static solve's grid resolves its shape (the quaternion-FD polygon: CheckPolygon).
/// On the SE(3) path RK4 in s turns each section through
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
#include "cosserat/state/rod_state.hpp"

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
  /// The largest bending turn per segment (rad), where (s of its segment's start, m) and its
  /// curvature (1/m).
  double worst_turn = 0.0, worst_s = 0.0, worst_k = 0.0;
};

/// From the nodes' s (m), positions (m) and curvatures [k1, k2, k3] (1/m, body frame) of a rod
/// of length L: the runaway check on the whole turn |κ| h, the warning (above 0.5 rad per
/// segment) on the bending part sqrt(k1² + k2²) h, with the error it implies and the nodes that
/// would keep it below 0.25. converged false: the state is the last load level a continuation
/// reached, and the log says so. stretch: the axial strain at each node (empty: none), which
/// the check of RK4's shrinking frames leaves out of the nodes' spacing.
GridResolution CheckGrid(const std::vector<double>& s, const std::vector<Vec3>& position,
                         const std::vector<Vec3>& curvature, double length,
                         bool converged = true, const std::vector<double>& stretch = {});
/// The same on a solver's state (its s, positions and the curvature part of its strains), which
/// also finds frames that left the rotations (FramesLeftRotationsLine).
GridResolution CheckGrid(const RodState& state, double length, bool converged = true);
/// Where a shot's frames left the rotations (FrameRanAway) while no segment ran away: the line
/// that says so (status non_finite) and names the nodes that keep the bending below 0.25 rad per
/// segment; empty otherwise.
std::string FramesLeftRotationsLine(const RodState& state, double length);

/// The quaternion-FD grid's: the bending curvature at the vertices times the spacing, or where
/// larger the turn between the segments meeting at a vertex, atan2(|a × b|, a · b). The scheme
/// is second order: a
/// constant-curvature arc's tip is off by about 0.08 (κ h)² L (measured: 7.1e-3 L at κ h = 0.31
/// and 1.9e-3 L at 0.16 on a quarter circle, 3.2e-2 L at 0.63 on a whole one); warning above
/// 0.5 rad, under_resolved above 1.5 rad (86° at a vertex). A bend that sharp over a short
/// stretch costs far less than the arc's figure: a soft cantilever's clamp layer at κ h = 0.99
/// (51 nodes) leaves its tip 0.19 % of L off, where the arc's figure is 7.8 %.
/// The twist is judged on the strain, κ₃ less `rest_twist` (1/m at each node; empty: none).
GridResolution CheckPolygon(const std::vector<double>& s, const std::vector<Vec3>& position,
                            const std::vector<Vec3>& curvature, double length,
                            const std::vector<double>& rest_twist = {});

/// SE(3) statics: where the rod is in tension T its bending settles over 1/k = sqrt(EI/T) (a layer
/// at a clamp, a support or a load), which RK4 in s follows per segment as its polynomial
/// 1 + z + z²/2 + z³/6 + z⁴/24 follows e^z, z = k h: 0.5 % short at k h = 1.1, 7 % at 2.2 (a
/// rope hanging from a clamp, EI = 10 N·m², 3 kN: its clamp reaction 0.12 % and 5.6 % low). A
/// warning line from the nodes' s, axial force (body z) and the section's smaller EI where the
/// largest k h costs more than 1 %, naming the nodes that keep it below 1; empty otherwise.
std::string TensionLayerLine(const io::Problem& problem, const nlohmann::ordered_json& nodes);

/// The same for a converged statics or modes result (either formulation), from its nodes (for
/// modes, the equilibrium they are about): a runaway makes it non_finite, a grid under_resolved
/// makes it under_resolved (exit 1). A statics stopped short (load_stepping_failed) keeps its
/// status and gets the same lines about its last level.
void CheckGridResolution(const io::Problem& problem, Result* result);

}  // namespace cosserat::run
