#pragma once
/// \file
/// "analysis": "buckling": the critical load along the problem's "buckling" load path, for the
/// cantilever and the column end conditions (docs/buckling.md).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// SE(3) shooting (BucklingAnalysis). Result::json holds the statics keys of the pre-buckled
/// equilibrium at the critical load (or at the last load reached) and a "buckling" block
/// {critical_load (N, N·m, m/s² or N/m: the unit of the load searched; null if none up to "max"),
/// mode_s_max (m; null if none), status, ...}; the node table is that equilibrium's. Converged
/// unless the load path could not be followed.
Result RunBuckling(const io::Problem& problem, const RunOptions& options);

/// The same on the "quaternion-fd" formulation (QuatFdBuckling: the smallest eigenvalue of the
/// static stiffness; cantilever only, rod.nodes − 1 segments). The "buckling" block has the same
/// keys except the mode's shape: critical_load, mode_s_max, status, load, direction, boundary,
/// load_reached, static_solves, and "multiplicity" (2: a double root).
Result RunQuatFdBuckling(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
