#pragma once
// `cosserat solve` for "formulation": "quaternion-fd" (Lang & Linn 2009): statics by Newton on the
// discrete equilibrium, dynamics with the banded Rosenbrock integrator. Same result JSON as the
// SE(3) path.

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Statics: returns true when the solve converged.
bool RunQuatFdStatics(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                      std::ostream& log);

/// Dynamics from rest in static equilibrium under the initial loads; the trajectory is recorded
/// every output_interval, `dt` is the integrator's first trial step (the step is adaptive, relative
/// tolerance 1e-6). Returns true when the initial state converged and the run reached the end.
bool RunQuatFdDynamics(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                       std::ostream& log);

}  // namespace cosserat::cli
