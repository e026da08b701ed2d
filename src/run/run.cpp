#include "cosserat/run/run.hpp"

#include "cosserat/run/grid_resolution.hpp"

#include <cmath>
#include <string>

#include "bending_stress_report.hpp"
#include "contact_report.hpp"
#include "scale_warnings.hpp"
#include "cosserat/loads/obstacle_core.hpp"
#include "cosserat/run/run_assembly.hpp"
#include "cosserat/run/run_buckling.hpp"
#include "cosserat/run/run_dynamics.hpp"
#include "cosserat/run/run_eversion.hpp"
#include "cosserat/run/run_modes.hpp"
#include "cosserat/run/run_quatfd.hpp"
#include "cosserat/run/run_statics.hpp"

namespace cosserat::run {

namespace {

Result Dispatch(const io::Problem& problem, const RunOptions& options) {
  using io::Analysis;
  const bool dynamics = problem.analysis == Analysis::kDynamics;
  if (problem.has_assembly) return RunAssembly(problem, options);
  if (problem.analysis == Analysis::kModes) return RunModes(problem, options);
  if (problem.formulation == io::Formulation::kQuaternionFd) {
    if (problem.analysis == Analysis::kBuckling) return RunQuatFdBuckling(problem, options);
    return dynamics ? RunQuatFdDynamics(problem, options) : RunQuatFdStatics(problem, options);
  }
  if (problem.analysis == Analysis::kBuckling) return RunBuckling(problem, options);
  if (problem.has_robot && problem.robot.kind == io::RobotKind::kEversion)
    return RunEversion(problem, options);
  return dynamics ? RunDynamics(problem, options) : RunStatics(problem, options);
}

/// True when a number somewhere in j is not finite (the writer would print it as null).
bool HasNonFinite(const nlohmann::ordered_json& j) {
  if (j.is_number_float()) return !std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const auto& v : j)
      if (HasNonFinite(v)) return true;
  return false;
}

/// A converged solve whose state holds NaN or Inf (a degenerate but accepted input, such as a
/// rod of 1e-300 m) is no answer: its status becomes non_finite, never a silent null.
void RefuseNonFiniteAnswers(Result* result) {
  if (!result->converged) return;
  for (const char* key : {"tip", "base_wrench", "nodes", "modes", "buckling", "robot", "assembly"}) {
    if (!result->json.contains(key) || !HasNonFinite(result->json[key])) continue;
    result->converged = false;
    result->json["status"] = ToString(SolveStatus::kNonFinite);
    result->log += std::string("cosserat: the solve converged, but its result holds NaN or Inf (in \"") +
                   key + "\"): status non_finite; check the rod's scales\n";
    return;
  }
}

/// A continuation that failed beside a contact surface may have been held back by the statics'
/// obstacle rule (obstacle_core.hpp): say so.
void ObstacleHint(const io::Problem& problem, Result* result) {
  if (result->converged || !HasObstacleCore(problem.loads.contact) ||
      result->json.value("status", "") != ToString(SolveStatus::kLoadSteppingFailed))
    return;
  result->log +=
      "cosserat: hint: load steps that would take the rod through a contact surface (its "
      "centreline within half the radius of a sphere's centre or a post's axis, or beyond a "
      "plane or a bore's wall) are refused: the surface's stiffness may be too low for the "
      "load, or (quaternion-fd, where contact acts at the nodes) the obstacle smaller than the "
      "node spacing\n";
}

}  // namespace

Result Run(const io::Problem& problem, const RunOptions& options) {
  Result result = Dispatch(problem, options);
  RefuseNonFiniteAnswers(&result);
  CheckGridResolution(problem, &result);
  ObstacleHint(problem, &result);
  detail::AddContactReport(problem, &result);
  detail::AddFrameContactForces(problem, &result);
  detail::AddBendingStressReport(problem, &result);
  detail::AddScaleWarnings(problem, &result);
  return result;
}

}  // namespace cosserat::run
