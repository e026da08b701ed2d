#pragma once
// `cosserat solve` for "analysis": "dynamics": BDF2 shooting from rest in static equilibrium.

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Simulates `problem` (a validated dynamics problem), writes the result JSON to `out`, the node
/// positions of every recorded frame to `csv` when given, and a one-line summary to `log`.
/// Returns true when the initial state and every step converged.
bool RunDynamics(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                 std::ostream& log);

}  // namespace cosserat::cli
