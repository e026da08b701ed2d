#pragma once
// The "assembly" block of a result, for the statics (run_assembly.cpp) and the dynamics
// (run_assembly_dynamics.cpp) of an assembly.

#include <nlohmann/json.hpp>
#include <vector>

#include "cosserat/assembly/assembly.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::run::detail {

/// {kind, bodies [{name, position (m), rotation (R_WB, rows)}], rods [{name, length (m), tip,
/// base_wrench, nodes {s, position, curvature, moment_body, force_body}}]} for the bodies at
/// `poses` and rod i in `rods[i]` at `lengths[i]`.
nlohmann::ordered_json AssemblyJson(const Assembly& assembly, const char* kind,
                                    const std::vector<lie::SE3>& poses,
                                    const std::vector<const RodState*>& rods,
                                    const std::vector<double>& lengths);

}  // namespace cosserat::run::detail
