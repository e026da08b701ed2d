#pragma once
/// \file
/// "analysis": "dynamics" on the SE(3) path: BDF2 shooting from rest in static equilibrium.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Simulates a dynamics problem (cantilever or free-free). The node table holds the node
/// positions of every recorded frame. Converged when the initial state and every step converged;
/// a failed step at small dt adds a hint on multiple shooting to Result::log.
Result RunDynamics(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
