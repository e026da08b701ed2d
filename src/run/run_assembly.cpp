#include "cosserat/run/run_assembly.hpp"

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/assembly/assembly_statics.hpp"
#include "cosserat/io/csv_line.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/run/run_assembly_dynamics.hpp"

#include "assembly_json.hpp"

namespace cosserat::run {
namespace {

using json = nlohmann::ordered_json;

/// The "assembly" block of the solver's last solution, without the Jacobian.
json SolutionToJson(const Assembly& assembly, bool inverse, AssemblyStaticsSolver* solver,
                    std::string* csv) {
  std::vector<const RodState*> rods;
  std::ostringstream table;
  table << "rod,s,x,y,z\n";
  io::CsvLine line;  // the shortest round-trip numbers, as a single rod's table
  for (int i = 0; i < solver->rod_count(); ++i) {
    const RodState& state = solver->rod_state(i);
    rods.push_back(&state);
    for (int n = 0; n < state.size(); ++n) {
      const Vec3& p = state.position_W[n];
      line << i << state.s[n] << p.x() << p.y() << p.z();
      line.WriteTo(table);
    }
  }
  if (csv) *csv = table.str();
  return detail::AssemblyJson(assembly, inverse ? "inverse" : "forward", solver->body_poses(),
                              rods, solver->lengths());
}

/// d pose / d lengths of body 0 (6 × rods) from a forward solve at the solver's lengths: after
/// an inverse solve this solve starts at its solution and returns at once. Null if it fails.
json PoseJacobianJson(const io::Problem& problem, AssemblyStaticsSolver* solver,
                      std::string* log) {
  if (problem.assembly.assembly.bodies.empty()) return nullptr;
  if (problem.assembly.inverse()) {
    const std::vector<double> lengths = solver->lengths();
    if (!solver->Solve(problem.loads, lengths).converged()) return nullptr;
  }
  const Eigen::MatrixXd J = solver->PoseJacobian(0, problem.loads);
  if (J.rows() != 6) return nullptr;
  if (!J.allFinite()) {  // an optional output: the poses and forces stand without it
    *log += "cosserat: note: pose_jacobian is not defined here (null): the first body's pose "
            "does not move smoothly with the rods' lengths (a body held only by pinned tips "
            "turns freely)\n";
    return nullptr;
  }
  json rows = json::array();
  for (int r = 0; r < 6; ++r) {
    json row = json::array();
    for (int c = 0; c < J.cols(); ++c) row.push_back(J(r, c));
    rows.push_back(row);
  }
  return rows;
}

std::string Summary(const io::Problem& problem, const AssemblySummary& s,
                    const AssemblyStaticsSolver& solver) {
  std::ostringstream line;
  line << "cosserat: " << ToString(s.status) << " (assembly, "
       << (problem.assembly.inverse() ? "inverse" : "forward") << "), " << s.iterations
       << " iterations, residual " << std::setprecision(3) << s.residual;
  const auto& bodies = problem.assembly.assembly.bodies;
  if (!bodies.empty()) {
    const lie::SE3& pose = solver.body_poses()[0];
    const Vec3 theta = lie::SO3Log(pose.R);
    line << std::setprecision(6) << ", " << bodies[0].name << " at [" << pose.p.x() << ", "
         << pose.p.y() << ", " << pose.p.z() << "] m, rotation vector [" << theta.x() << ", "
         << theta.y() << ", " << theta.z() << "] rad";
  }
  if (problem.assembly.inverse()) {
    line << ", lengths [";
    for (std::size_t i = 0; i < solver.lengths().size(); ++i)
      line << (i ? ", " : "") << std::setprecision(9) << solver.lengths()[i];
    line << "] m";
  }
  line << ", " << std::setprecision(3) << s.wall_time_s * 1e3 << " ms";
  if (s.status == SolveStatus::kLoadSteppingFailed)
    line << "; the continuation reached " << std::setprecision(3) << s.load_fraction
         << " of the loads: the state and residual written are that level's";
  if (problem.assembly.inverse() && !bodies.empty() && s.status == SolveStatus::kMaxIterations)
    line << "\ncosserat: hint: no rod lengths were found that hold " << bodies[0].name
         << " at this pose, which may be beyond the robot's reach (the lengths written are the "
            "last try); approach it in steps from a pose that solves";
  // Not even the first load step: a body free to move against its load has no equilibrium.
  if (s.status == SolveStatus::kLoadSteppingFailed && s.load_fraction == 0.0)
    line << "\ncosserat: hint: no part of the loads found an equilibrium, as when a body can "
            "move freely against them (a mechanism: a moment about the line through pinned "
            "tips, a turn about a torsion-free tip's axis, a body on one pinned rod; hold it "
            "against that motion with more rods or clamped tips), or when the rods cannot "
            "reach their attachments on the bodies (check each tip.attachment against the "
            "rod's length)";
  return line.str();
}

}  // namespace

Result RunAssembly(const io::Problem& problem, const RunOptions& options) {
  if (problem.analysis == io::Analysis::kDynamics) return RunAssemblyDynamics(problem, options);
  const io::Problem::AssemblyProblem& spec = problem.assembly;
  AssemblyOptions opt;
  opt.tolerance = problem.solver.tolerance;
  opt.max_iterations = problem.solver.max_iterations;
  AssemblyStaticsSolver solver(spec.assembly, opt);
  const AssemblySummary summary = spec.inverse()
                                      ? solver.SolveLengths(problem.loads, spec.inverse_poses)
                                      : solver.Solve(problem.loads, spec.lengths);
  Result result;
  result.converged = summary.converged();
  result.log = Summary(problem, summary, solver) + '\n';
  json& out = result.json;
  out["status"] = ToString(summary.status);
  out["iterations"] = summary.iterations;
  out["jacobians"] = summary.jacobians;
  out["load_steps"] = summary.load_steps;
  out["residual"] = summary.residual;
  if (summary.status == SolveStatus::kLoadSteppingFailed)
    out["load_reached"] = summary.load_fraction;
  out["wall_time_s"] = summary.wall_time_s;
  out["assembly"] = SolutionToJson(spec.assembly, spec.inverse(), &solver,
                                   options.nodes_csv ? &result.nodes_csv : nullptr);
  out["assembly"]["pose_jacobian"] =
      summary.converged() ? PoseJacobianJson(problem, &solver, &result.log) : json(nullptr);
  // After PoseJacobianJson the solver holds the forward solution at the result's lengths (for an
  // inverse, its own equilibrium).
  const int index = summary.converged() ? solver.BodyStabilityIndex(problem.loads) : -1;
  if (index >= 0) out["assembly"]["stability_index"] = index;
  if (index > 0)
    result.log += "cosserat: warning: the bodies' equilibrium is unstable (" +
                  std::to_string(index) + " direction" + (index > 1 ? "s" : "") +
                  " in which their condensed stiffness pushes them on): " +
                  (problem.assembly.inverse()
                       ? "these lengths hold the poses only in an unstable equilibrium"
                       : "the loads are past a critical one") +
                  " (docs/assemblies.md, \"Stability\")\n";
  return result;
}

}  // namespace cosserat::run
