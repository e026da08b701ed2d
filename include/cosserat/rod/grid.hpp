#pragma once
/// \file
/// Discretisation of [0, L] into grid nodes that include every profile breakpoint, so a jump in
/// stiffness never falls inside an integration step.

#include <vector>

#include "cosserat/rod/rod_model.hpp"

namespace cosserat {

/// Returns num_nodes arc lengths 0 = s_0 < … < s_{N−1} = length (m). The interior breakpoints
/// split [0, L] into pieces; each piece gets a share of the N − 1 segments proportional to its
/// length (at least one), and is divided uniformly. Without breakpoints the grid is uniform.
/// Breakpoints outside (0, L) or closer than 1e-12 L to another are ignored.
/// Requires num_nodes >= 2 + (number of distinct interior breakpoints).
std::vector<double> MakeGrid(double length, int num_nodes, std::vector<double> breakpoints);

/// The grid of a model with num_nodes nodes (its profile's breakpoints among them). Throws
/// std::invalid_argument saying what is wrong when the model is invalid or num_nodes < 2.
std::vector<double> ModelGrid(const RodModel& model, int num_nodes);

/// Where an RK4 step over each segment [s_i, s_{i+1}] of the grid reads the section: its start,
/// its midpoint, and its end moved 1e-9 h inside, so that a step never reads the far side of a
/// breakpoint at a node. Three values per segment, in order (m).
std::vector<double> SegmentSamplePoints(const std::vector<double>& grid);

}  // namespace cosserat
