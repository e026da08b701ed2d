#pragma once
/// \file
/// The "rod" object of a problem file (length, nodes, section, material, rest curvature,
/// stiffness profile), the largest section of the format, apart from the rest of problem.cpp.

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// Sets problem->rod and problem->nodes from `rod`, reporting every error; what is invalid keeps
/// its default.
void ParseRod(const ObjectReader& rod, Problem* problem);

}  // namespace cosserat::io::detail
