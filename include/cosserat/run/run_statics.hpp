#pragma once
/// \file
/// "analysis": "statics" on the SE(3) path: the cantilever's equilibrium, with a tendon robot's
/// tensions (or, under displacement control, the tensions that give the commanded tendon
/// lengths), or a column's ("pinned-pinned", "clamped-clamped", "clamped-pinned"; plain rods,
/// loads followed from the unloaded column).

#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"
#include "cosserat/state/solve_status.hpp"

namespace cosserat::run {

/// Solves a statics problem; a tendon robot adds a "robot" block (tensions, lengths, slack) to
/// Result::json. Converged when the solve converged.
Result RunStatics(const io::Problem& problem, const RunOptions& options);

/// Why a tendon robot's static solve under `actuation` ended in non-finite numbers, when the
/// tendon strain law is the likely cause (Rucker & Webster 2011: K (ξ − ξ*) + T(ξ) = W has no
/// solution the shot can reach at a section): a "cosserat: hint: " line naming the tendon with
/// the largest tension × offset² / EI. Empty for any other status, a rod without tendons, or
/// that ratio below 0.5 (another cause).
std::string TendonLawHint(const io::Problem& problem, const Actuation& actuation,
                          SolveStatus status);

}  // namespace cosserat::run
