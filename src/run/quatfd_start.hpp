#pragma once
/// \file
/// The other formulation's equilibrium as a start for the SE(3) solvers: a rod lying along a
/// stiff contact surface (a pipe on a bore's wall) is out of reach of the SE(3) statics' load
/// steps, as each Newton step from the unloaded rod sags it through the surface and the steps
/// shrink to nothing, while the quaternion-FD statics solve it directly from the straight rod.
/// The SE(3) solvers refine that state on their own equations.

#include <optional>

#include "cosserat/io/problem.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::run::detail {

/// The quaternion-FD equilibrium of `problem`'s clamped rod at `base` under `loads` and
/// `actuation`, on the nodes the SE(3) solvers use (ModelGrid). Empty when the quaternion-FD
/// statics do not take the problem, do not converge, or lay their vertices elsewhere.
std::optional<RodState> QuatFdEquilibriumOnGrid(const io::Problem& problem,
                                                const lie::SE3& base, const StaticLoads& loads,
                                                const Actuation& actuation);

}  // namespace cosserat::run::detail
