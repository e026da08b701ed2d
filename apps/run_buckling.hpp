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

/// The same on the "quaternion-fd" formulation (QuatFdBuckling: the smallest eigenvalue of the
/// static stiffness; cantilever only, rod.nodes − 1 segments). The "buckling" block has the same
/// keys except the mode's shape: critical_load, mode_s_max, status, load, direction, boundary,
/// load_reached, static_solves, and "multiplicity" (2: a double root).
bool RunQuatFdBuckling(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                       std::ostream& log);

}  // namespace cosserat::cli
