#pragma once
/// \file
/// The contact part of a result: the force per unit length the surfaces exert at each node
/// (`nodes.contact_force`, N/m, world frame) and its integral along s (`contact.total_force`, N:
/// in SE(3) statics and modes without other pose-dependent loads, from the rod's force balance,
/// which holds the contact at the shot's own stages; otherwise the trapezoid rule on the nodes,
/// the quaternion-FD model's own lumping), from the nodes of the result's (final) state; plus
/// the s-intervals in
/// contact; the statics node table gets the same forces as columns contact_fx, contact_fy,
/// contact_fz. In dynamics the damping and the friction are taken at the final state's node
/// velocities (Result::node_velocity_W).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::run::detail {

/// Adds "contact" and "nodes.contact_force" to result->json when the problem has contact
/// surfaces and the result has nodes.
void AddContactReport(const io::Problem& problem, Result* result);

/// With contact surfaces, each recorded frame's contact force per unit length at every node
/// (N/m, world; io::VtkFrame::contact_force), at the frame's node velocities.
void AddFrameContactForces(const io::Problem& problem, Result* result);

/// The touchdown point of a state: the s of the last node of the first stretch of nodes, from
/// the base, whose sections press into a contact surface (their centreline nearer to it than
/// their outer radius); NaN when none does.
double TouchdownS(const io::Problem& problem, const RodState& state);

}  // namespace cosserat::run::detail
