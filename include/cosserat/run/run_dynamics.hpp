#pragma once
/// \file
/// "analysis": "dynamics" on the SE(3) path: BDF2 shooting from rest in static equilibrium.

#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Simulates a dynamics problem (cantilever or free-free). The node table holds the node
/// positions of every recorded frame. Converged when the initial state and every step converged;
/// a failed step at small dt adds a hint on multiple shooting to Result::log.
Result RunDynamics(const io::Problem& problem, const RunOptions& options);

/// The warnings a run of the problem's rod at time step dt (s) gets before it starts, one line
/// each ("cosserat: warning: ..."): a first bending mode BDF2 resolves in under ~6 steps, and a
/// shear wave above 1 per segment (automatic pieces only). Empty when neither applies. The CLI
/// logs them; the Python steppers raise them as warnings.
std::string DynamicsStartWarnings(const io::Problem& problem, double dt);

}  // namespace cosserat::run
