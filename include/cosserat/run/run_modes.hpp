#pragma once
/// \file
/// "analysis": "modes": natural frequencies and mode shapes of the cantilever about its static
/// equilibrium under the problem's loads, on either formulation (docs/modes.md).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Result::json holds "modes": {"frequencies_hz": [...], "shapes": [...], ...} and the
/// equilibrium under "equilibrium"; the node table is the equilibrium's. Converged when the
/// equilibrium converged and modes.count modes were found.
Result RunModes(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
