#include "cosserat/run/run_eversion.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "cosserat/io/result_writer.hpp"
#include "cosserat/robots/eversion_robot.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "cosserat/run/solver_options.hpp"
#include "frame_output.hpp"
#include "growth_record.hpp"
#include "node_table.hpp"

namespace cosserat::run {
namespace {

/// A vine pushed along its axis past its Euler load, or grown taller than its own weight lets
/// it stand, stays straight in the solve and is unstable there: a warning line, else empty.
std::string UnstableBodyWarning(const StaticShootingSummary& solve) {
  if (!solve.converged() || solve.stability_index <= 0) return "";
  std::ostringstream line;
  line << "cosserat: warning: this equilibrium is unstable (" << solve.stability_index
       << " unstable direction" << (solve.stability_index > 1 ? "s" : "") << "): the body is "
       << "past a critical load (a push along it beyond its Euler load, or a height its own "
       << "weight cannot stand) and would buckle sideways from this shape; the same tube "
       << "without the robot block runs \"analysis\": \"buckling\"\n";
  return line.str();
}

/// The result's robot.kink block.
nlohmann::ordered_json KinkJson(const KinkReport& kink) {
  nlohmann::ordered_json k;
  k["status"] = ToString(kink.status);
  k["max_moment_ratio"] = std::isfinite(kink.max_ratio) ? nlohmann::ordered_json(kink.max_ratio)
                                                        : nlohmann::ordered_json(nullptr);
  k["s_max"] = kink.s_max;
  k["moment"] = kink.moment;
  k["torque"] = kink.torque;
  // Where the ratio first reaches 1 (m); null when it never does.
  k["first_kink_s"] = kink.first_kink_s >= 0 ? nlohmann::ordered_json(kink.first_kink_s)
                                             : nlohmann::ordered_json(nullptr);
  return k;
}

/// The summary line's words on a kink, " (… at s = … m: …)", or empty for none. The ratio is
/// |m|/M_w without torque; a torque's share of the membrane's shear joins it.
std::string KinkWords(const KinkReport& kink, double pressure) {
  std::ostringstream words;
  words << std::setprecision(6);
  const char* ratio_name = kink.torque > 1e-6 * kink.moment ? "wrinkling ratio" : "|m|/M_w";
  if (!std::isfinite(kink.max_ratio))
    words << " (at s = " << kink.s_max << " m the wall has no tension left: "
          << (kink.wrinkling_moment > 0.0 ? "uninflated (p = 0) and twisted, "
              : pressure > 0.0 ? "pushed along its axis, or pulled back by its tail, past the "
                                 "pressure's force, "
                                          : "uninflated (p = 0) and not pulled taut, ")
          << "and a film carries no compression)";
  else if (kink.status == KinkStatus::kCollapsed)
    words << " (" << ratio_name << " = " << kink.max_ratio << " at s = " << kink.s_max
          << " m: the tube folds there; the shape beyond is not modelled)";
  else if (kink.kinked())
    words << " (" << ratio_name << " = " << kink.max_ratio << " at s = " << kink.s_max
          << " m: the wall wrinkles there; it folds at 2)";
  return words.str();
}

/// The result's "robot": its kind, pressure (Pa), length (m), tip force and tail tension (N) and
/// kink report.
nlohmann::ordered_json RobotJson(const EversionRobot& robot, const KinkReport& kink) {
  nlohmann::ordered_json r;
  r["kind"] = io::ToString(io::RobotKind::kEversion);
  r["pressure"] = robot.pressure();
  r["length"] = robot.length();
  r["tip_force"] = robot.TipForce();
  r["tail_tension"] = robot.tail_tension();
  r["kink"] = KinkJson(kink);
  return r;
}

}  // namespace

Result RunEversion(const io::Problem& problem, const RunOptions& run_options) {
  // The parser guarantees an inflated-tube profile for this kind.
  const auto& tube = dynamic_cast<const InflatedTubeSection&>(*problem.rod.section);
  const EversionRobotDesign design = DesignFromTube(tube, problem.rod.length, problem.base);
  EversionOptions options;
  options.solver = StaticOptions(problem);
  // The body is gridded by length as it grows: at rod.nodes' density over rod.length, and at
  // least the robot's default (40 per metre).
  const double asked_density = (problem.nodes - 1) / problem.rod.length;  // nodes per metre
  options.nodes_per_metre = std::max(options.nodes_per_metre, asked_density);
  const double pressure = problem.robot.actuation.pressure;
  const double start = problem.robot.growth_initial_length.value_or(problem.rod.length);
  EversionRobot robot(design, start, pressure, options);
  robot.SetTailTension(problem.robot.tail_tension);

  StaticShootingSummary solve;
  KinkReport kink;
  std::ostringstream growth_note;
  nlohmann::ordered_json first_kink_length;  // grown: the length first kinked at (m), or null
  bool converged;
  detail::GrowthRecord growth(run_options.frames);
  if (problem.robot.growth_initial_length) {
    const GrowthSummary g = robot.Grow(
        problem.rod.length, problem.robot.growth_steps, problem.loads,
        [&growth](int, const EversionSolveSummary& step, const EversionRobot& r) {
          growth.Add(r, step);
        });
    converged = g.converged();
    solve = g.last_solve;
    solve.status = g.status;
    kink = g.worst_kink;
    growth_note << ", grown in " << g.steps << " steps";
    if (g.first_kink_step >= 0)
      growth_note << ", first kink at L = " << g.first_kink_length << " m";
    first_kink_length = g.first_kink_step >= 0 ? nlohmann::ordered_json(g.first_kink_length)
                                                : nlohmann::ordered_json(nullptr);
  } else {
    const EversionSolveSummary s = robot.Solve(problem.loads);
    // As after growth: the exit code follows the solve (status); a kink is the robot's report.
    converged = s.solve.converged();
    solve = s.solve;
    kink = s.kink;
  }
  Result result;
  result.json = io::StaticResultToJson(solve, robot.state());
  if (robot.pieces() > 1) result.json["shooting_segments"] = robot.pieces();  // the last solve's
  detail::KeepStaticFrame(problem, robot.state(), run_options, &result);
  growth.MoveFramesInto(&result);  // a grown robot: every step's body
  nlohmann::ordered_json r = RobotJson(robot, kink);
  if (problem.robot.growth_initial_length) {
    r["first_kink_length"] = first_kink_length;
    r["growth"] = growth.Json();
  }
  result.json["robot"] = r;
  if (run_options.nodes_csv) result.nodes_csv = detail::NodesCsv(robot.state());
  const Vec3 tip = robot.state().tip_position_W();
  std::ostringstream log;
  log << "cosserat: eversion " << ToString(solve.status) << growth_note.str()
      << ", L = " << robot.length() << " m, tip at [" << std::setprecision(6) << tip.x() << ", "
      << tip.y() << ", " << tip.z() << "] m"
      << (robot.pieces() > 1 ? " (" + std::to_string(robot.pieces()) + " shooting pieces)" : "")
      << ", kink"
      << (problem.robot.growth_initial_length ? " (the worst met while growing)" : "") << ": "
      << ToString(kink.status);
  log << KinkWords(kink, pressure) << '\n';
  log << UnstableBodyWarning(solve);
  if (asked_density < EversionOptions{}.nodes_per_metre)
    log << "cosserat: note: rod.nodes (" << problem.nodes << ") gives "
        << std::setprecision(3) << asked_density << " nodes per metre; an eversion robot's body "
        << "is gridded at " << options.nodes_per_metre << " at least (" << robot.state().size()
        << " nodes here)\n";
  result.log = log.str();
  result.converged = converged;
  return result;
}

}  // namespace cosserat::run
