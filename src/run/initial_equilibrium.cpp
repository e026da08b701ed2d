#include "cosserat/run/initial_equilibrium.hpp"

#include <optional>
#include <stdexcept>
#include <utility>

#include "cosserat/analysis/column.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "quatfd_start.hpp"
#include "statics_in_pieces.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::run {

StaticLoads WithTipMassWeight(const io::Problem& problem, StaticLoads loads) {
  if (problem.dynamics.tip_mass > 0 && loads.tip_force_frame == LoadFrame::kWorld)
    loads.tip_force += problem.dynamics.tip_mass * loads.gravity_W;
  return loads;
}

namespace {

/// Whether one shot from the clamp resolves the rod's statics (StaticShootingExponent ≤ 10), as
/// the statics runner decides: beyond that a stiff contact foundation or a high tension needs
/// multiple shooting, and a single shot from a rigid-body guess may settle on a looped shape.
bool SingleShotResolves(const io::Problem& problem, const StaticLoads& loads) {
  return StaticShootingExponent(problem.rod, WithTipMassWeight(problem, loads)) <= 10.0;
}

/// The clamped rod's equilibrium under `input` (its base pose, loads and actuation; the tip
/// mass's weight included) from the statics solver with its continuation in the load, in pieces
/// where one shot cannot resolve it (plain rods: the statics runner takes no actuation, tendons
/// or chambers in pieces), or on contact surfaces from the quaternion-FD equilibrium where the
/// load steps fail (quatfd_start.hpp; the pieces' solve tries it itself). Empty if none
/// converges. *index receives the solve's count of unstable directions (−1: none).
std::optional<RodState> StaticEquilibrium(const io::Problem& problem, const StepInput& input,
                                          int* index) {
  *index = -1;
  const StaticShootingOptions single = StaticOptions(problem);
  const StaticLoads statics_loads = WithTipMassWeight(problem, input.loads);
  if (!problem.has_robot && problem.rod.tendons.empty() && problem.rod.chambers.empty() &&
      !SingleShotResolves(problem, input.loads)) {
    detail::StaticsInPieces solved = detail::SolveStaticsInPieces(
        problem, ColumnEnds::kClampedFree, input.base_pose, statics_loads);
    if (!solved.summary.converged()) return std::nullopt;
    *index = solved.summary.stability_index;
    return std::move(solved.state);
  }
  StaticShootingSolver solver(problem.rod, problem.nodes, single, input.actuation);
  const StaticShootingSummary summary = solver.Solve(input.base_pose, statics_loads);
  if (summary.converged()) {
    *index = summary.stability_index;
    return solver.state();
  }
  if (input.loads.contact.count == 0) return std::nullopt;
  return detail::QuatFdEquilibriumOnGrid(problem, input.base_pose, statics_loads,
                                         input.actuation);
}

}  // namespace

std::optional<RodState> StaticEquilibriumToStartFrom(const io::Problem& problem,
                                                     const StepInput& input,
                                                     int* unstable_directions) {
  int index = -1;
  if (unstable_directions) *unstable_directions = -1;
  try {
    std::optional<RodState> out = StaticEquilibrium(problem, input, &index);
    if (unstable_directions) *unstable_directions = index;
    return out;
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a rod the statics solvers do not take
  }
}

std::optional<RodState> RunawayStartState(const io::Problem& problem, const StepInput& input) {
  if (problem.boundary != io::Boundary::kCantilever) return std::nullopt;
  try {
    StaticShootingSolver solver(problem.rod, problem.nodes, StaticOptions(problem),
                                input.actuation);
    solver.Solve(input.base_pose, WithTipMassWeight(problem, input.loads));
    if (solver.state().RanAway()) return solver.state();
  } catch (const std::invalid_argument&) {
  }  // a rod the statics solver does not take
  return std::nullopt;
}

StepSummary InitializeAtStaticEquilibrium(const io::Problem& problem, const StepInput& input,
                                          Bdf2ShootingStepper* stepper,
                                          int* unstable_directions) {
  if (unstable_directions) *unstable_directions = -1;
  const bool column = GuidedTipHold(problem.boundary) != TipHold::kFree;
  if (problem.boundary != io::Boundary::kCantilever && !column)
    return stepper->InitializeAtRest(input);
  StepSummary counted;
  std::optional<RodState> equilibrium;
  if (column) {  // the column solver's, followed from the unloaded column as its statics are
    ColumnEnds ends;
    ToColumnEnds(problem.boundary, &ends);
    ColumnSolver solver(problem.rod, problem.nodes, ends, StaticOptions(problem),
                        input.actuation);
    if (solver.SolveFromUnloaded(problem.base, input.loads).converged()) {
      equilibrium = solver.state();
      if (unstable_directions)
        *unstable_directions = solver.StabilityIndexAtUnknowns(problem.base, input.loads);
    }
  } else {
    equilibrium = StaticEquilibriumToStartFrom(problem, input, unstable_directions);
  }
  if (equilibrium) {
    const StepSummary from_statics = stepper->InitializeAtRest(input, *equilibrium);
    if (from_statics.converged()) return from_statics;
    counted = from_statics;
  }
  if (unstable_directions) *unstable_directions = -1;  // the stepper's own start: not counted
  StepSummary own = stepper->InitializeAtRest(input);
  own.iterations += counted.iterations;
  own.shots += counted.shots;
  own.jacobians += counted.jacobians;
  own.wall_time_s += counted.wall_time_s;
  return own;
}

}  // namespace cosserat::run
