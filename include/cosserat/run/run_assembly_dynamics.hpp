#pragma once
/// \file
/// Dynamics of a problem of rods and rigid bodies ("assembly" with "analysis": "dynamics";
/// docs/assemblies.md, "Dynamics"): the structure at rest in equilibrium under the initial loads
/// (dynamics.initial_loads, bodies[j].initial_force and .initial_moment), then round(duration /
/// dt) BDF2 steps under the loads (AssemblyDynamics).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Result::json: status, steps, simulated_time_s, wall_time_s, failed_at_t (null when it ran
/// through), "trajectory" {t (s), energy (J), bodies [{name, position [[x, y, z] per frame] (m),
/// rotation_vector (rad, world: R_WB = Exp(θ)), velocity (m/s, world)}]}, and "assembly" (as the
/// statics result: the bodies' poses and the rods' shapes at the last step; kind "dynamics").
/// Result::nodes_csv: `t,rod,s,x,y,z` for every rod at every frame.
Result RunAssemblyDynamics(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
