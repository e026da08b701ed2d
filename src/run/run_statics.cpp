#include "cosserat/run/run_statics.hpp"

#include <array>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/analysis/column.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/robots/tendon_control.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "node_table.hpp"

namespace cosserat::run {
namespace {

std::string StaticSummary(const StaticShootingSummary& s, const RodState& state) {
  std::ostringstream line;
  line << "cosserat: " << ToString(s.status) << ", " << s.iterations << " iterations, "
       << "residual " << std::setprecision(3) << s.residual;
  if (state.size() > 0) {
    const Vec3& tip = state.tip_position_W();
    line << ", tip at [" << std::setprecision(6) << tip.x() << ", " << tip.y() << ", " << tip.z()
         << "] m";
  }
  line << ", " << std::setprecision(3) << s.wall_time_s * 1e3 << " ms";
  return line.str();
}

/// A column (boundary "pinned-pinned", "clamped-clamped" or "clamped-pinned"): the loads
/// followed from the straight, unloaded column (ColumnSolver::SolveFromUnloaded).
Result RunColumnStatics(const io::Problem& problem, ColumnEnds ends, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ColumnSolver solver(problem.rod, problem.nodes, ends, StaticOptions(problem));
  const ColumnSummary column = solver.SolveFromUnloaded(problem.base, problem.loads);
  StaticShootingSummary summary;  // the result's fields, from the column solve
  summary.status = column.status;
  summary.iterations = column.iterations;
  summary.shots = column.shots;
  summary.load_steps = column.load_steps;
  summary.residual = column.residual;
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Result result;
  result.json = io::StaticResultToJson(summary, solver.state());
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(solver.state());
  result.log = StaticSummary(summary, solver.state()) + " (" + ToString(ends) + ")\n";
  result.converged = summary.converged();
  return result;
}

/// A cantilever whose single shot would amplify errors beyond double precision (a stiff
/// contact foundation, a high tension): multiple shooting in pieces it chooses.
Result RunMultipleShootingStatics(const io::Problem& problem, const RunOptions& options) {
  const StaticShootingOptions single = StaticOptions(problem);
  StaticMultipleShootingOptions opt;
  opt.tolerance = single.tolerance;
  opt.max_iterations = single.max_iterations;
  StaticMultipleShootingSolver solver(problem.rod, problem.nodes, opt);
  const StaticShootingSummary summary = solver.Solve(problem.base, problem.loads);
  Result result;
  result.json = io::StaticResultToJson(summary, solver.state());
  result.json["shooting_segments"] = solver.pieces();
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(solver.state());
  result.log = StaticSummary(summary, solver.state()) + " (" + std::to_string(solver.pieces()) +
               " shooting pieces)\n";
  result.converged = summary.converged();
  return result;
}

}  // namespace

Result RunStatics(const io::Problem& problem, const RunOptions& options) {
  ColumnEnds ends = ColumnEnds::kClampedFree;
  if (problem.boundary != io::Boundary::kCantilever && ToColumnEnds(problem.boundary, &ends))
    return RunColumnStatics(problem, ends, options);
  if (!problem.has_robot && problem.rod.tendons.empty() &&
      StaticShootingExponent(problem.rod, problem.loads) > 10.0)
    return RunMultipleShootingStatics(problem, options);
  Actuation actuation = problem.robot.actuation;
  StaticShootingSolver solver(problem.rod, problem.nodes, StaticOptions(problem), actuation);
  StaticShootingSummary summary = solver.Solve(problem.base, problem.loads);
  std::array<bool, Actuation::kMaxTendons> slack{};
  for (int i = 0; i < Actuation::kMaxTendons; ++i)
    slack[i] = actuation.tendon_tension[i] == 0.0;  // force control: slack means no tension
  if (problem.robot.tendon_lengths && summary.converged()) {
    // Displacement control: the tensions that give the commanded tendon lengths.
    const TendonLengthSummary t = SolveTendonLengths(solver, problem.base, problem.loads,
                                                     *problem.robot.tendon_lengths, &actuation);
    summary.status = t.status;
    summary.iterations += t.iterations;
    slack = t.slack;
  }
  Result result;
  result.json = io::StaticResultToJson(summary, solver.state());
  if (problem.has_robot) {
    const int count = solver.tendon_count();
    nlohmann::ordered_json robot;
    robot["kind"] = io::ToString(problem.robot.kind);
    robot["tendon_tension"] = std::vector<double>(actuation.tendon_tension.begin(),
                                                  actuation.tendon_tension.begin() + count);
    robot["tendon_length"] = std::vector<double>(solver.tendon_lengths().begin(),
                                                 solver.tendon_lengths().begin() + count);
    robot["tendon_slack"] = std::vector<bool>(slack.begin(), slack.begin() + count);
    if (!problem.rod.chambers.empty())
      robot["chamber_pressure"] =
          std::vector<double>(actuation.chamber_pressure.begin(),
                              actuation.chamber_pressure.begin() + problem.rod.chambers.size());
    result.json["robot"] = robot;
  }
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(solver.state());
  result.log = StaticSummary(summary, solver.state()) + '\n';
  result.converged = summary.converged();
  return result;
}

}  // namespace cosserat::run
