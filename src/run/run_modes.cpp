#include "cosserat/run/run_modes.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "frame_output.hpp"
#include "node_table.hpp"

namespace cosserat::run {
namespace {

nlohmann::ordered_json Vectors(const std::vector<Vec3>& v) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Vec3& x : v) out.push_back({x.x(), x.y(), x.z()});
  return out;
}

/// SE(3) modes shoot the rod in one piece from the clamp, statics and frequency scan alike: a
/// tension or a foundation beyond what one shot resolves is the other formulation's.
std::string SingleShotHint(const io::Problem& problem, const ModalResult& r) {
  if (problem.formulation == io::Formulation::kQuaternionFd ||
      r.status != ModalStatus::kStaticsFailed)
    return "";
  const double exponent = StaticShootingExponent(problem.rod, problem.loads);
  if (!(exponent > 10.0)) return "";
  std::ostringstream hint;
  hint << std::setprecision(3)
       << "cosserat: hint: SE(3) modes shoot the rod in one piece from the clamp (statics and "
          "frequency scan), and its loads give L sqrt(T/EI) (or L (k/4EI)^(1/4) for a "
          "foundation) = "
       << exponent << ", beyond the ~10 one shot resolves: use \"formulation\": "
                      "\"quaternion-fd\"\n";
  return hint.str();
}

/// SE(3) modes found fewer frequencies than asked: above λL ≈ 20, λ = (ω² ρA/EI)^¼, one shot
/// amplifies round-off by e^{λL} and the scan's roots blur (a 0.5 m, 1 mm steel rod lost partners
/// of its 9th and 10th pairs, at λL ≈ 24–27). Says where that begins.
std::string HighModesHint(const io::Problem& problem, const ModalResult& r) {
  if (problem.formulation == io::Formulation::kQuaternionFd ||
      r.status != ModalStatus::kTooFewModes || !problem.rod.section)
    return "";
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double rhoA = p.mass(3, 3), EI = p.min_bending_stiffness(), L = problem.rod.length;
  const double f20 = std::pow(20.0 / L, 2) * std::sqrt(EI / rhoA) / (2 * M_PI);
  std::ostringstream hint;
  hint << std::setprecision(3) << "cosserat: hint: SE(3) modes shoot the rod in one piece, "
       << "which resolves frequencies up to about " << f20
       << " Hz here (λL = 20, λ = (ω² ρA/EI)^(1/4)); above it the roots blur: ask for fewer "
          "modes, or use \"formulation\": \"quaternion-fd\"\n";
  return hint.str();
}

}  // namespace

Result RunModes(const io::Problem& problem, const RunOptions& options) {
  const bool quatfd = problem.formulation == io::Formulation::kQuaternionFd;
  ModalOptions mo;
  mo.count = problem.modes.count;
  ModalResult r;
  if (quatfd) {
    quatfd::QuatFdModel model(problem.rod, problem.base, QuatFdModelOptions(problem),
                              problem.robot.actuation);
    model.set_loads(problem.loads);  // the start of a held rod's statics sags along gravity
    r = ComputeModes(&model, problem.loads, mo, nullptr, nullptr, QuatFdStaticOptions(problem));
  } else {
    ShootingModalOptions so;
    so.modal = mo;
    so.statics = StaticOptions(problem);
    r = ComputeModesShooting(problem.rod, problem.nodes, problem.base, problem.loads, so,
                             problem.robot.actuation);
  }

  // The contract's fields of every result (status, iterations, residual, tip, base_wrench,
  // nodes) describe the equilibrium the modes are about; "modes" and the statics' own status
  // ("equilibrium") follow.
  StaticShootingSummary eq;
  eq.status = r.statics_status;
  eq.iterations = r.statics_iterations;
  eq.residual = r.statics_residual;
  const nlohmann::ordered_json statics = io::StaticResultToJson(eq, r.equilibrium);
  Result result;
  detail::KeepStaticFrame(problem, r.equilibrium, options, &result);
  result.json["status"] = ToString(r.status);
  for (const char* key : {"iterations", "residual"}) result.json[key] = statics[key];
  result.json["wall_time_s"] = r.wall_time_s;
  for (const char* key : {"tip", "base_wrench", "nodes"})
    if (statics.contains(key)) result.json[key] = statics[key];
  if (problem.boundary == io::Boundary::kAnchored && r.equilibrium.size() > 0) {
    // As the statics report it: the force the tip's anchor exerts on the rod (N, world).
    const Vec3 f = r.equilibrium.rotation_WB.back() * r.equilibrium.wrench_B.back().tail<3>();
    result.json["anchor_force"] = {f.x(), f.y(), f.z()};
  }
  nlohmann::ordered_json modes;
  modes["formulation"] = io::ToString(problem.formulation);
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
  result.json["modes"] = modes;
  result.json["equilibrium"] = {{"status", ToString(r.statics_status)}};
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(r.equilibrium);

  std::ostringstream log;
  log << "cosserat: " << ToString(r.status) << " (modes, " << io::ToString(problem.formulation)
      << "), " << r.modes.size() << " modes:";
  for (const Mode& m : r.modes) log << ' ' << std::setprecision(6) << m.frequency_hz;
  log << " Hz, " << std::setprecision(3) << r.wall_time_s * 1e3 << " ms\n";
  if (r.status == ModalStatus::kUnstable && !r.instability.empty())
    log << "cosserat: unstable: " << r.instability << "\n";
  result.log = log.str() + SingleShotHint(problem, r) + HighModesHint(problem, r);
  result.converged = r.converged();
  return result;
}

}  // namespace cosserat::run
