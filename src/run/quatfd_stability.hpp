#pragma once
/// \file
/// The stability of a quaternion-FD cantilever equilibrium: the number of negative eigenvalues
/// of its static stiffness (QuatFdBuckling::StiffnessEigenvalues), the Morse index the SE(3)
/// statics report as stability_index.

#include <Eigen/Core>

#include "cosserat/io/problem.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::run::detail {

/// The unstable directions of the equilibrium q (the model of MakeQuatFdModel(problem)) with
/// its RodState `state`, counted by the inertia of the banded stiffness
/// (QuatFdBuckling::StiffnessEigenvaluesBelow, O(N)); −1 when not checked: not a cantilever,
/// loads that are not conservative (follower or world tip moments, a flow's drag, a robot's
/// actuation), or a factorisation too near singular to count on a grid too fine for its
/// eigenvalues; 0 with no compression anywhere and no contact surface (a rod nowhere compressed
/// does not buckle).
int QuatFdStabilityIndex(const io::Problem& problem, const Eigen::VectorXd& q,
                         const RodState& state);

}  // namespace cosserat::run::detail
