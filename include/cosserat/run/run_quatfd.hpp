#pragma once
/// \file
/// "formulation": "quaternion-fd" (Lang & Linn): statics by Newton on the discrete equilibrium,
/// dynamics with the Radau IIA integrator. Same result document as the SE(3) path.

#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/run/result.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::run {

/// The problem's quaternion-FD model with its loads set (a rod held at both ends then starts from
/// a shape that sags along their gravity).
quatfd::QuatFdModel MakeQuatFdModel(const io::Problem& problem);

/// The static equilibrium of `model` under the problem's loads from its start (RestState), node
/// values into *state: the quaternion-FD statics, and the start of the SE(3) solve of a rod held
/// at both ends. With q_out, also the model's state vector.
quatfd::QuatFdStaticsSummary SolveQuatFdEquilibrium(const io::Problem& problem,
                                                    quatfd::QuatFdModel* model, RodState* state,
                                                    Eigen::VectorXd* q_out = nullptr);

/// After a converged quaternion-FD equilibrium (statics, or the modes' about it) of a rod
/// anchored with a clamped end: the end moment comes from the first segments' bending, which a
/// grid coarser than half the bending boundary layer sqrt(EI/T) there under-resolves. A warning
/// line naming the nodes for a spacing of 0.25 sqrt(EI/T); empty otherwise.
std::string ClampedEndGridWarning(const io::Problem& problem, const RodState& state);

/// Statics of the cantilever. Converged when the solve converged.
Result RunQuatFdStatics(const io::Problem& problem, const RunOptions& options);

/// Dynamics from rest in static equilibrium under the initial loads; the trajectory is recorded
/// every output_interval, dt is the integrator's first trial step (the step is adaptive, to
/// dynamics.integrator_tolerance). Converged when the initial state converged and the run reached
/// the end.
Result RunQuatFdDynamics(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
