#pragma once
/// \file
/// The statics of a plain rod (no tendons or chambers) by multiple shooting, for the runners:
/// the equilibrium, its stability index from Jacobi fields carried piece by piece, and for a
/// cantilever the stable branch when a whole load step landed on an unstable equilibrium.

#include "cosserat/analysis/column.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::run::detail {

struct StaticsInPieces {
  /// Status, counts (of every solve tried) and the stability index (−1: not defined or not
  /// converged).
  StaticShootingSummary summary;
  RodState state;  ///< the equilibrium when converged, else the last load level's state
  int pieces = 1;
};

/// The stability index of an equilibrium multiple shooting found in `pieces` pieces under
/// `loads` at `base`: the Jacobi fields carried piece by piece along it
/// (ColumnSolver::StabilityIndexInPieces, any ends), as one shot from the base would amplify
/// rounding beyond use there (a stiff contact, a high tension). −1 where it is not defined.
int IndexInPieces(const io::Problem& problem, ColumnEnds ends, const lie::SE3& base,
                  const StaticLoads& loads, const RodState& state, int pieces);

/// The multiple-shooting options of the problem's solver settings for these ends and pieces (0:
/// chosen from the loads); stepped: its loads followed in levels that turn no section by more
/// than 0.5 rad (always for a column).
StaticMultipleShootingOptions PiecesOptions(const io::Problem& problem, ColumnEnds ends,
                                            int pieces, bool stepped);

/// The problem's rod with these ends at `base` under `loads`, in `pieces` pieces (0: chosen from
/// the loads), by continuation from the unloaded rod. A column's path starts with a step of 3 in
/// the load parameter and grows while no section turns by more than 0.5 rad a level. A
/// cantilever takes the whole load at once; if that fails, ends on an unstable equilibrium, or
/// on one whose count could not be formed under conservative loads, it is followed again in such
/// steps, and that answer is kept if it converges where the first did not or has fewer unstable
/// directions.
StaticsInPieces SolveStaticsInPieces(const io::Problem& problem, ColumnEnds ends,
                                     const lie::SE3& base, const StaticLoads& loads,
                                     int pieces = 0);

}  // namespace cosserat::run::detail
