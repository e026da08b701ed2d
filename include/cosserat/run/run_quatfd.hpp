#pragma once
/// \file
/// "formulation": "quaternion-fd" (Lang & Linn): statics by Newton on the discrete equilibrium,
/// dynamics with the Radau IIA integrator. Same result document as the SE(3) path.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Statics of the cantilever. Converged when the solve converged.
Result RunQuatFdStatics(const io::Problem& problem, const RunOptions& options);

/// Dynamics from rest in static equilibrium under the initial loads; the trajectory is recorded
/// every output_interval, dt is the integrator's first trial step (the step is adaptive, to
/// dynamics.integrator_tolerance). Converged when the initial state converged and the run reached
/// the end.
Result RunQuatFdDynamics(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
