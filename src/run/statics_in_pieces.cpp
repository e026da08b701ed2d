#include "statics_in_pieces.hpp"

#include <optional>

#include "cosserat/loads/total_load.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "quatfd_start.hpp"

namespace cosserat::run::detail {
namespace {

/// The most a section may turn between two levels of a cantilever's stepped path (rad): a soft
/// rod held out level under its weight, which ends hanging (π/2 at the clamp), follows its path
/// in a few tens of levels.
constexpr double kMostTurnPerLevel = 0.5;

StaticsInPieces SolveOnce(const io::Problem& problem, ColumnEnds ends, const lie::SE3& base,
                          const StaticLoads& loads, const StaticMultipleShootingOptions& opt) {
  StaticMultipleShootingSolver solver(problem.rod, problem.nodes, opt);
  StaticsInPieces out;
  out.summary = solver.Solve(base, loads);
  out.state = solver.state();
  out.pieces = solver.pieces();
  if (out.summary.converged())
    out.summary.stability_index = IndexInPieces(problem, ends, base, loads, out.state, out.pieces);
  return out;
}

/// The cantilever refined by Newton in pieces from the quaternion-FD equilibrium on the same
/// nodes (QuatFdEquilibriumOnGrid); not converged when there is none.
StaticsInPieces FromQuatFdEquilibrium(const io::Problem& problem, const lie::SE3& base,
                                      const StaticLoads& loads, int pieces) {
  StaticsInPieces out;
  out.summary.status = SolveStatus::kMaxIterations;
  const std::optional<RodState> guess =
      QuatFdEquilibriumOnGrid(problem, base, loads, problem.robot.actuation);
  if (!guess) return out;
  StaticMultipleShootingSolver solver(
      problem.rod, problem.nodes, PiecesOptions(problem, ColumnEnds::kClampedFree, pieces, false));
  out.summary = solver.SolveFrom(base, loads, *guess);
  out.state = solver.state();
  out.pieces = solver.pieces();
  if (out.summary.converged())
    out.summary.stability_index =
        IndexInPieces(problem, ColumnEnds::kClampedFree, base, loads, out.state, out.pieces);
  return out;
}

}  // namespace

int IndexInPieces(const io::Problem& problem, ColumnEnds ends, const lie::SE3& base,
                  const StaticLoads& loads, const RodState& state, int pieces) {
  if (!problem.rod.tendons.empty() || state.size() < 2) return -1;
  const ColumnSolver column(problem.rod, problem.nodes, ends, StaticOptions(problem),
                            problem.robot.actuation);
  // A cantilever counts as its single shot does (ColumnSolver::StabilityIndexFromShot).
  const double zero = ends == ColumnEnds::kClampedFree ? 1e-8 : 0.0;
  return column.StabilityIndexInPieces(base, loads, state, pieces, zero);
}

StaticMultipleShootingOptions PiecesOptions(const io::Problem& problem, ColumnEnds ends,
                                            int pieces, bool stepped) {
  const StaticShootingOptions single = StaticOptions(problem);
  StaticMultipleShootingOptions opt = MultipleShootingOptionsFor(ends);
  opt.pieces = pieces;
  opt.tolerance = single.tolerance;
  opt.max_iterations = single.max_iterations;
  if (opt.tip_guided || stepped) opt.max_turn = kMostTurnPerLevel;
  return opt;
}

StaticsInPieces SolveStaticsInPieces(const io::Problem& problem, ColumnEnds ends,
                                     const lie::SE3& base, const StaticLoads& loads,
                                     int pieces) {
  StaticMultipleShootingOptions opt = PiecesOptions(problem, ends, pieces, false);
  StaticsInPieces first = SolveOnce(problem, ends, base, loads, opt);
  // A cantilever that a whole step did not take to a stable equilibrium: one unstable (a soft rod
  // held out level under its weight, looped up over its clamp), one whose count could not be
  // formed under conservative loads (the same loop on a grid too coarse for it), or none. Its
  // loads are followed again in steps that turn no section far, as the single shot's solve keeps
  // the stable branch (StaticShootingOptions::stable_branch). The first answer stands unless the
  // path converges where it did not, or ends with fewer unstable directions.
  const int index = first.summary.stability_index;
  const bool unjudged = index < 0 && LoadsAreConservative(loads);
  if (ends != ColumnEnds::kClampedFree ||
      (first.summary.converged() && index == 0) ||
      (first.summary.converged() && index < 0 && !unjudged))
    return first;
  opt.max_turn = kMostTurnPerLevel;
  StaticsInPieces again = SolveOnce(problem, ends, base, loads, opt);
  const StaticShootingSummary& s = again.summary;
  const bool better =
      s.converged() &&
      (!first.summary.converged() ||
       (s.stability_index >= 0 && (index < 0 || s.stability_index < index)));
  StaticsInPieces& kept = better ? again : first;
  const StaticShootingSummary& other = better ? first.summary : again.summary;
  kept.summary.CountWorkOf(other);
  if (!kept.summary.converged() && loads.contact.count > 0) {
    // A rod lying along a stiff surface, which the load steps do not reach (quatfd_start.hpp).
    StaticsInPieces from_fd = FromQuatFdEquilibrium(problem, base, loads, pieces);
    if (from_fd.summary.converged()) {
      from_fd.summary.CountWorkOf(kept.summary);
      return from_fd;
    }
  }
  return kept;
}

}  // namespace cosserat::run::detail
