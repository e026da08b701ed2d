#pragma once
// `cosserat solve` for "analysis": "statics" on the SE(3) path: the cantilever's equilibrium, with
// a tendon robot's tensions (or, under displacement control, the tensions that give the commanded
// tendon lengths), or a column's ("pinned-pinned", "clamped-clamped", "clamped-pinned"; plain rods,
// loads followed from the unloaded column).

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Solves a statics problem; the result JSON to `out`, the node table to `csv` when given, the
/// summary line to `log`. Returns true when the solve converged.
bool RunStatics(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                std::ostream& log);

}  // namespace cosserat::cli
