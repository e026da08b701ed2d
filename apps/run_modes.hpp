#pragma once
// `cosserat solve` for "analysis": "modes": natural frequencies and mode shapes of the cantilever
// about its static equilibrium under the problem's loads, on either formulation
// (docs/modes.md). The result holds "modes": {"frequencies_hz": [...], "shapes": [...], ...} and
// the equilibrium under "equilibrium".

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Returns true when the equilibrium converged and modes.count modes were found.
bool RunModes(const io::Problem& problem, std::ostream& out, std::ostream* csv, std::ostream& log);

}  // namespace cosserat::cli
