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
/// (QuatFdBuckling::StiffnessEigenvaluesBelow); −1 when not checked: not a cantilever, loads that
/// are not conservative (follower or world tip moments, a flow's drag, a robot's actuation), more
/// than kMaxCheckedNodes nodes (the stiffness is built dense: 0.15 s and 70 MB at 201 nodes,
/// 0.5 s and 160 MB at 401, 1.8 s and 600 MB at 801), or no compression anywhere (then 0: a rod
/// nowhere compressed does not buckle).
int QuatFdStabilityIndex(const io::Problem& problem, const Eigen::VectorXd& q,
                         const RodState& state);

inline constexpr int kMaxCheckedNodes = 401;

}  // namespace cosserat::run::detail
