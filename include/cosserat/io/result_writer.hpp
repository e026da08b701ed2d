#pragma once
/// \file
/// Results of a solve as JSON (the "Result" of docs/problem-format.md) and as a CSV of the nodes.

#include <nlohmann/json.hpp>
#include <ostream>

#include "cosserat/strong/rod_state.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::io {

/// The statics result:
///   status (ToString of the status), iterations, shots, load_steps, residual, wall_time_s,
///   tip {position (m), rotation (R_WB, row-major 3×3)},
///   base_wrench {moment (N·m), force (N)}: the reaction of the support on the rod, world frame,
///     moment about the base point (RodState::BaseReaction_W),
///   nodes {s, position, curvature (body-frame [k1, k2, k3], 1/m),
///          moment_body, force_body (internal wrench W = [m; n] in the section frame)}.
/// Keys keep this order (status first). Non-finite numbers (only possible when the solve failed)
/// are written as null.
nlohmann::ordered_json StaticResultToJson(const StaticShootingSummary& summary, const RodState& state);

/// One row per node, header `s,x,y,z,k1,k2,k3` (m; 1/m), full double precision.
void WriteNodesCsv(std::ostream& out, const RodState& state);

}  // namespace cosserat::io
