#pragma once
/// \file
/// A problem of rods and rigid bodies ("assembly", docs/assemblies.md): forward statics (the
/// bodies' poses for the rods' lengths) or inverse statics (the lengths for the bodies' poses),
/// with the first body's pose Jacobian.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Result::json: status, iterations, jacobians, load_steps, residual, wall_time_s (the solve's),
/// and "assembly" {kind ("forward" | "inverse"), bodies [{name, position (m), rotation (R_WB,
/// rows)}], rods [{name, length (m), base_wrench {moment (N·m, about the base point), force (N)}
/// (the support's reaction on the rod, world), tip {position, rotation}, nodes {s, position}}],
/// pose_jacobian (6 × rods: d[p_W; θ]/dL of body 0, m/m and rad/m, θ in the body frame; from a
/// forward solve at the lengths; null if that failed)}. Result::nodes_csv: `rod,s,x,y,z` (rod
/// index from 0). Converged when the forward or inverse solve converged.
Result RunAssembly(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
