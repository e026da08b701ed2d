#pragma once
/// \file
/// The hint after a static solve with contact that failed on a grid too coarse for a surface's
/// foundation length ℓ = (4EI/k)^¼, the length over which the rod settles into it (EI the larger
/// bending stiffness at the base, k the surface's stiffness per length).

#include <string>

#include "cosserat/io/problem.hpp"

namespace cosserat::run::detail {

/// For the first contact surface whose ℓ the grid spacing h exceeds `spacings_per_length` × ℓ:
/// the line "cosserat: hint: the grid spacing h m is coarse for environment.contact[k]'s
/// foundation length ... m, <why>: try <advice>rod.nodes >= n<more>", n the node count for
/// h = spacings_per_length × ℓ. Empty when the grid resolves every surface.
std::string FoundationHint(const io::Problem& problem, double spacings_per_length,
                           const std::string& why, const std::string& advice,
                           const std::string& more);

}  // namespace cosserat::run::detail
