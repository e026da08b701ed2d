#pragma once
/// \file
/// "analysis": "modes": natural frequencies and mode shapes about the static equilibrium under
/// the problem's loads: of the cantilever on either formulation, of a column on the SE(3) path,
/// of a rod held at both ends ("anchored") on the quaternion-FD path (docs/modes.md).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Result::json holds "modes": {"frequencies_hz": [...], "shapes": [...], ...} and the
/// equilibrium under "equilibrium"; the node table is the equilibrium's. Converged when the
/// equilibrium converged and modes.count modes were found.
Result RunModes(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
