#pragma once
/// \file
/// A note on a rod that passes through itself. The model has no self-contact: a tendon robot
/// given tendon lengths it cannot reach coils three turns through its own backbone, where a
/// real rod would press on itself.

#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// "cosserat: note: ..." when two stretches of a statics equilibrium's nodes (converged, or
/// under-resolved) further apart along the rod than π times its outer diameter d come within d
/// of each other (segment to segment, world frame); empty otherwise, for sections with no outer
/// diameter, and for grids over 2 001 nodes (the check is quadratic in them).
std::string SelfCrossingNote(const io::Problem& problem, const Result& result);

}  // namespace cosserat::run::detail
