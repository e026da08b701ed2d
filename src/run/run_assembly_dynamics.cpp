#include "cosserat/run/run_assembly_dynamics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cosserat/assembly/assembly_dynamics.hpp"
#include "cosserat/io/csv_line.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/run/solver_options.hpp"
#include "assembly_json.hpp"
#include "frame_output.hpp"

namespace cosserat::run {
namespace {

using json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

/// What a run records at every output frame.
struct Frames {
  json t = json::array(), energy = json::array();
  std::vector<json> position, rotation, velocity;  ///< per body, a list of frames
  std::ostringstream csv;
};

/// `t`: the frame's time, k dt after k steps (the stepper's own clock sums the steps, rounding:
/// 8 s of 2 ms steps read 7.9999999999999174).
void Record(const AssemblyDynamics& dyn, double t, const StaticLoads& loads,
            const RunOptions& options, Frames* f, Result* result) {
  f->t.push_back(t);
  if (options.frames) {
    io::VtkFrame frame;
    frame.t = t;
    for (int i = 0; i < dyn.rod_count(); ++i) frame.rods.push_back(dyn.rod(i).state());
    for (int b = 0; b < dyn.body_count(); ++b) {
      frame.bodies.push_back(dyn.body_pose(b));
      frame.body_velocity_W.push_back(dyn.body_velocity_W(b));
    }
    result->frames.push_back(std::move(frame));
  }
  const bool nodes = options.nodes_csv;
  f->energy.push_back(dyn.Energy(loads));
  for (int b = 0; b < dyn.body_count(); ++b) {
    f->position[b].push_back(io::ToJson(dyn.body_pose(b).p));
    f->rotation[b].push_back(io::ToJson(lie::SO3Log(dyn.body_pose(b).R)));
    f->velocity[b].push_back(io::ToJson(dyn.body_velocity_W(b)));
  }
  if (!nodes) return;
  io::CsvLine line;  // the shortest round-trip numbers, as a single rod's table
  for (int i = 0; i < dyn.rod_count(); ++i) {
    const RodState& s = dyn.rod(i).state();
    for (int n = 0; n < s.size(); ++n) {
      line << t << i << s.s[n] << s.position_W[n].x() << s.position_W[n].y()
           << s.position_W[n].z();
      line.WriteTo(f->csv);
    }
  }
}

json FinalState(const Assembly& assembly, const AssemblyDynamics& dyn) {
  std::vector<lie::SE3> poses;
  for (int b = 0; b < dyn.body_count(); ++b) poses.push_back(dyn.body_pose(b));
  std::vector<const RodState*> rods;
  std::vector<double> lengths;
  for (int i = 0; i < dyn.rod_count(); ++i) {
    rods.push_back(&dyn.rod(i).state());
    lengths.push_back(assembly.rods[i].model.length);
  }
  return detail::AssemblyJson(assembly, "dynamics", poses, rods, lengths);
}

/// The one-line summary of a run (and why it stopped).
std::string SummaryLine(const Assembly& assembly, const AssemblySummary& init, SolveStatus status,
                        int taken, double failed_at, double wall, const AssemblyDynamics& dyn) {
  std::ostringstream line;
  line << "cosserat: " << ToString(status) << " (assembly dynamics)";
  if (!init.converged() && dyn.failed_rod() >= 0) {
    // The statics converged; a rod's own solve at the bodies' poses did not.
    const StepSummary& rod = dyn.failed_rod_summary();
    line << ", the initial equilibrium did not converge: rod \""
         << assembly.rods[dyn.failed_rod()].name << "\"'s own solve at the bodies' poses ended "
         << ToString(rod.status) << " (residual " << std::setprecision(3) << rod.residual
         << "); more nodes on that rod may resolve it";
  } else if (!init.converged()) {
    line << ", the initial equilibrium did not converge (residual " << std::setprecision(3)
         << init.residual << ")";
  } else {
    if (status != SolveStatus::kConverged)
      line << " in the step to t = " << std::setprecision(6) << failed_at << " s";
    line << ", " << taken << " steps, " << std::setprecision(6) << dyn.time() << " s simulated in "
         << std::setprecision(3) << wall << " s";
    if (dyn.body_count() > 0) {
      const Vec3& p = dyn.body_pose(0).p;
      line << ", " << assembly.bodies[0].name << " at [" << std::setprecision(6) << p.x() << ", "
           << p.y() << ", " << p.z() << "] m";
    }
  }
  return line.str() + '\n';
}

/// The trajectory block: the frames' times, energies and each body's path.
json TrajectoryJson(const Assembly& assembly, const Frames& frames) {
  json bodies = json::array();
  for (std::size_t b = 0; b < assembly.bodies.size(); ++b)
    bodies.push_back({{"name", assembly.bodies[b].name},
                      {"position", frames.position[b]},
                      {"rotation_vector", frames.rotation[b]},
                      {"velocity", frames.velocity[b]}});
  return {{"t", frames.t}, {"energy", frames.energy}, {"bodies", bodies}};
}

}  // namespace

Result RunAssemblyDynamics(const io::Problem& problem, const RunOptions& options) {
  const io::Problem::AssemblyProblem& spec = problem.assembly;
  const io::Problem::Dynamics& d = problem.dynamics;
  AssemblyDynamicsOptions opt;
  opt.dt = d.dt;
  opt.rod.spatial_scheme = ToSpatialScheme(d.spatial_scheme);
  // solver.tolerance and max_iterations: the start at rest's statics; a step's balance is never
  // asked to be tighter than 1e-8 (the rods' own solves are its noise), only looser.
  opt.statics.tolerance = problem.solver.tolerance;
  opt.statics.max_iterations = problem.solver.max_iterations;
  opt.tolerance = std::max(opt.tolerance, problem.solver.tolerance);
  AssemblyDynamics dyn(spec.assembly, opt);
  const int B = dyn.body_count();
  const auto start = Clock::now();
  for (int b = 0; b < B; ++b) dyn.SetBodyLoad(b, spec.initial_force[b], spec.initial_moment[b]);
  const AssemblySummary init = dyn.InitializeAtRest(d.initial_loads.value_or(problem.loads));
  for (int b = 0; b < B; ++b)
    dyn.SetBodyLoad(b, spec.assembly.bodies[b].force_W, spec.assembly.bodies[b].moment_W);

  Result result;
  if (options.frames)
    for (int i = 0; i < dyn.rod_count(); ++i)
      result.node_radius.push_back(detail::NodeRadius(spec.assembly.rods[i].model,
                                                      dyn.rod(i).state().s, Actuation{}));
  Frames frames;
  frames.position.assign(B, json::array());
  frames.rotation.assign(B, json::array());
  frames.velocity.assign(B, json::array());
  frames.csv << "t,rod,s,x,y,z\n";
  const auto [steps, stride] = detail::StepsOf(d);
  SolveStatus status = init.status;
  int taken = 0, iterations = init.iterations;
  double residual = init.residual;  // the largest final residual of the solves
  double failed_at = -1.0;
  if (init.converged()) {
    Record(dyn, 0.0, problem.loads, options, &frames, &result);
    for (int k = 1; k <= steps; ++k) {
      const AssemblySummary s = dyn.Step(problem.loads);
      iterations += s.iterations;
      residual = std::max(residual, s.residual);
      if (!s.converged()) {
        status = s.status;
        failed_at = k * d.dt;
        break;
      }
      ++taken;
      if (k % stride == 0 || k == steps)
        Record(dyn, k * d.dt, problem.loads, options, &frames, &result);
      if (options.progress) options.progress(k * d.dt, d.duration);
    }
  } else {
    failed_at = 0.0;
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();

  result.converged = status == SolveStatus::kConverged;
  json& out = result.json;
  out["status"] = ToString(status);
  out["steps"] = taken;
  out["iterations"] = iterations;
  out["residual"] = residual;
  out["simulated_time_s"] = taken * d.dt;
  out["wall_time_s"] = wall;
  if (failed_at >= 0) out["failed_at_t"] = failed_at;  // only when the run failed, as a rod's
  out["trajectory"] = TrajectoryJson(spec.assembly, frames);
  out["assembly"] = FinalState(spec.assembly, dyn);
  if (options.nodes_csv) result.nodes_csv = frames.csv.str();

  result.log = SummaryLine(spec.assembly, init, status, taken, failed_at, wall, dyn);
  return result;
}

}  // namespace cosserat::run
