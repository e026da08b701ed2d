#pragma once
/// \file
/// The "rod" object of a problem file (length, nodes, section, material, rest curvature,
/// stiffness profile), the largest section of the format, apart from the rest of problem.cpp.

#include <vector>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// Sets problem->rod and problem->nodes from `rod`, reporting every error; what is invalid keeps
/// its default.
void ParseRod(const ObjectReader& rod, Problem* problem);

/// Breakpoints strictly inside (0, L), counted the way MakeGrid places nodes on them: with the
/// two ends, the fewest rod.nodes that hold them.
int InteriorBreakpoints(std::vector<double> cuts, double length);

}  // namespace cosserat::io::detail
