#pragma once
/// \file
/// `cosserat solve` for "analysis": "buckling": the critical load along the problem's
/// "buckling" load path, for the cantilever and the column end conditions (docs/buckling.md).

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Writes the result JSON to `out`: the statics keys for the pre-buckled equilibrium at the
/// critical load (or at the last load reached), and a "buckling" block {critical_load (N, N·m,
/// m/s² or N/m: the unit of the load searched; null if none up to "max"), mode_s_max (m; null
/// if none), status, ...}. The node table of that equilibrium goes to `csv` if given, a summary
/// line to `log`. True unless the load path could not be followed.
bool RunBuckling(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                 std::ostream& log);

}  // namespace cosserat::cli
