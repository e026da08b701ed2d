#pragma once
/// \file
/// Solver options a problem file implies, shared by the command-line tool and the Python module.

#include "cosserat/io/problem.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat::io {

/// The BDF2 shooting stepper's options for a dynamics problem: "dynamics" (dt, tip body,
/// shooting_segments, spatial_scheme), "boundary" (cantilever or free-free) and "solver"
/// (tolerance, max_iterations).
Bdf2Options DynamicsOptions(const Problem& problem);

}  // namespace cosserat::io
