#pragma once
/// \file
/// "analysis": "statics" on the SE(3) path: the cantilever's equilibrium, with a tendon robot's
/// tensions (or, under displacement control, the tensions that give the commanded tendon
/// lengths), or a column's ("pinned-pinned", "clamped-clamped", "clamped-pinned"; plain rods,
/// loads followed from the unloaded column).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Solves a statics problem; a tendon robot adds a "robot" block (tensions, lengths, slack) to
/// Result::json. Converged when the solve converged.
Result RunStatics(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
