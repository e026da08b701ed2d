#include "cosserat/io/problem_options.hpp"

namespace cosserat::io {

Bdf2Options DynamicsOptions(const Problem& problem) {
  Bdf2Options options;
  options.dt = problem.dynamics.dt;
  options.ends =
      problem.boundary == "free-free" ? EndConditions::kFreeFree : EndConditions::kCantilever;
  options.tolerance = problem.solver.tolerance;
  options.tip_mass = problem.dynamics.tip_mass;
  options.tip_inertia_B = problem.dynamics.tip_inertia;
  options.max_iterations = problem.solver.max_iterations;
  options.shooting_segments = problem.dynamics.shooting_segments;
  options.spatial_scheme =
      problem.dynamics.spatial_scheme == "heun" ? SpatialScheme::kHeun : SpatialScheme::kRk4;
  return options;
}

}  // namespace cosserat::io
