#include "run_modes.hpp"

#include <iomanip>
#include <vector>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::cli {
namespace {

nlohmann::ordered_json Vectors(const std::vector<Vec3>& v) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Vec3& x : v) out.push_back({x.x(), x.y(), x.z()});
  return out;
}

}  // namespace

bool RunModes(const io::Problem& problem, std::ostream& out, std::ostream* csv, std::ostream& log) {
  const bool quatfd = problem.formulation == "quaternion-fd";
  ModalOptions mo;
  mo.count = problem.modes.count;
  ModalResult r;
  if (quatfd) {
    quatfd::QuatFdOptions options;
    options.segments = problem.nodes - 1;
    quatfd::QuatFdModel model(problem.rod, problem.base, options, problem.robot.actuation);
    quatfd::QuatFdStaticsOptions so;
    so.tolerance = problem.solver.tolerance;
    so.floor_tolerance = std::max(so.floor_tolerance, so.tolerance);
    so.max_iterations = problem.solver.max_iterations;
    r = ComputeModes(&model, problem.loads, mo, nullptr, nullptr, so);
  } else {
    ShootingModalOptions so;
    so.modal = mo;
    so.statics = problem.solver;
    r = ComputeModesShooting(problem.rod, problem.nodes, problem.base, problem.loads, so,
                             problem.robot.actuation);
  }

  nlohmann::ordered_json result;
  result["status"] = ToString(r.status);
  nlohmann::ordered_json modes;
  modes["formulation"] = problem.formulation;
  modes["frequencies_hz"] = r.frequencies_hz();
  std::vector<std::string> kinds;
  for (const Mode& m : r.modes) kinds.push_back(ToString(m.kind));
  modes["kinds"] = kinds;
  if (!r.damped.empty()) {
    std::vector<double> fd, zeta;
    for (const DampedMode& d : r.damped) {
      fd.push_back(d.damped_frequency_hz);
      zeta.push_back(d.damping_ratio);
    }
    modes["damped_frequencies_hz"] = fd;
    modes["damping_ratios"] = zeta;
  }
  modes["s"] = r.s;
  nlohmann::ordered_json shapes = nlohmann::ordered_json::array();
  for (const Mode& m : r.modes)
    shapes.push_back(
        {{"displacement", Vectors(m.displacement_W)}, {"rotation", Vectors(m.rotation_W)}});
  modes["shapes"] = shapes;
  result["modes"] = modes;
  StaticShootingSummary eq;
  eq.status = r.statics_status;
  nlohmann::ordered_json equilibrium = io::StaticResultToJson(eq, r.equilibrium);
  for (const char* key : {"iterations", "shots", "load_steps", "residual", "wall_time_s"})
    equilibrium.erase(key);
  result["equilibrium"] = equilibrium;
  result["wall_time_s"] = r.wall_time_s;
  out << result.dump(2) << '\n';
  if (csv) io::WriteNodesCsv(*csv, r.equilibrium);

  log << "cosserat: " << ToString(r.status) << " (modes, " << problem.formulation << "), "
      << r.modes.size() << " modes:";
  for (const Mode& m : r.modes) log << ' ' << std::setprecision(6) << m.frequency_hz;
  log << " Hz, " << std::setprecision(3) << r.wall_time_s * 1e3 << " ms\n";
  return r.converged();
}

}  // namespace cosserat::cli
