#include "cosserat/run/run.hpp"

#include "cosserat/run/grid_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "bending_stress_report.hpp"
#include "clamp_alignment_note.hpp"
#include "contact_report.hpp"
#include "drill_string_notes.hpp"
#include "scale_warnings.hpp"
#include "self_crossing_note.hpp"
#include "cosserat/loads/obstacle_core.hpp"
#include "cosserat/loads/total_load.hpp"
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
/// obstacle rule (obstacle_core.hpp): say so. The surface's stiffness is named as a cause only
/// when the rod's distributed load alone would press it in by a fifth of its radius or more (a
/// 300 m pipe sinking 0.3 mm into a bore was told its bore was too soft).
void ObstacleHint(const io::Problem& problem, Result* result) {
  const ContactSurfaces& surfaces = problem.loads.contact;
  if (result->converged || !HasObstacleCore(surfaces) ||
      result->json.value("status", "") != ToString(SolveStatus::kLoadSteppingFailed))
    return;
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double pressing =
      TotalDistributedForce_W(problem.loads, LoadSite{0.0, 1.0, p.mass(3, 3), p.outer_diameter})
          .norm();  // N/m
  double softest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < surfaces.count; ++i)
    if (surfaces.surface[i].stiffness > 0)
      softest = std::min(softest, surfaces.surface[i].stiffness);
  const bool soft = pressing / softest > 0.1 * p.outer_diameter;
  result->log += std::string(
                     "cosserat: hint: load steps that would take the rod through a contact "
                     "surface (its centreline within half the radius of a sphere's centre or a "
                     "post's axis, or beyond a plane or a bore's wall) are refused") +
                 (soft ? ": the surface's stiffness may be too low for the load" : "") +
                 "; (quaternion-fd, where contact acts at the nodes) the obstacle may be smaller "
                 "than the node spacing, and a grid coarser than the contact's bending length "
                 "(4 EI/k)^(1/4) follows the rod on it poorly\n";
}

/// A dynamics block kept in a file run for another analysis is checked and not used (the
/// format's rule); its base drive is the one setting a reader may think still acts (modes of a
/// spinning drill string hold no spin), so the log says it does not.
void UnusedBaseDriveNote(const io::Problem& problem, Result* result) {
  if (problem.analysis == io::Analysis::kDynamics || !problem.has_dynamics) return;
  const bool spin = problem.dynamics.base_spin != 0.0;
  if (!spin && !(problem.dynamics.rotary_table.inertia > 0)) return;
  result->log += std::string("cosserat: note: dynamics.") +
                 (spin ? "base_spin" : "rotary_table") +
                 " turns the base in \"analysis\": \"dynamics\" only; this \"" +
                 io::ToString(problem.analysis) + "\" holds the base still" +
                 (problem.analysis == io::Analysis::kModes ? " (no gyroscopic effect of a spin)"
                                                           : "") +
                 "\n";
}

/// A file without "analysis" is statics; one that holds the block of another analysis was
/// likely meant to run it, so the log says which ran and what to write.
void DefaultAnalysisNote(const io::Problem& problem, Result* result) {
  if (problem.analysis_given || problem.analysis != io::Analysis::kStatics) return;
  const char* block = problem.has_dynamics ? "dynamics"
                      : problem.has_buckling ? "buckling"
                      : problem.has_modes    ? "modes"
                                             : nullptr;
  if (!block) return;
  result->log += std::string("cosserat: note: the file gives no \"analysis\", so this is "
                             "statics (the default) and its \"") +
                 block + "\" block is not used; \"analysis\": \"" + block + "\" runs it\n";
}

/// The summary line (the log's first) names the status the checks after the solve left: a
/// converged solve whose shape ran away or that the grid under-resolves said "converged" there,
/// and a dynamics run stopped as under_resolved whose final state ran away said that.
void SummaryLineStatus(Result* result) {
  const std::string status = result->json.value("status", "");
  if (status.empty()) return;
  for (SolveStatus s : {SolveStatus::kConverged, SolveStatus::kUnderResolved}) {
    const std::string said = std::string("cosserat: ") + ToString(s);
    if (status != ToString(s) && result->log.rfind(said, 0) == 0) {
      result->log.replace(0, said.size(), std::string("cosserat: ") + status);
      return;
    }
  }
}

/// The log's warnings, also in the result (its last key, "warnings": the text after
/// "cosserat: warning: " of each, [] when none): a sweep's rows and a notebook's dict keep them.
void WarningsIntoResult(Result* result) {
  if (!result->json.is_object()) return;
  const std::string prefix = "cosserat: warning: ";
  nlohmann::ordered_json warnings = nlohmann::ordered_json::array();
  std::istringstream lines(result->log);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(prefix, 0) == 0) warnings.push_back(line.substr(prefix.size()));
  result->json["warnings"] = std::move(warnings);
}

}  // namespace

Result Run(const io::Problem& problem, const RunOptions& options) {
  Result result = Dispatch(problem, options);
  DefaultAnalysisNote(problem, &result);
  RefuseNonFiniteAnswers(&result);
  CheckGridResolution(problem, &result);
  ObstacleHint(problem, &result);
  detail::AddContactReport(problem, &result);
  detail::AddFrameContactForces(problem, &result);
  detail::AddBendingStressReport(problem, &result);
  detail::AddScaleWarnings(problem, &result);
  UnusedBaseDriveNote(problem, &result);
  result.log += detail::DrillStringNotes(problem) + detail::ClampAlignmentNote(problem, result) +
                detail::SelfCrossingNote(problem, result);
  SummaryLineStatus(&result);
  WarningsIntoResult(&result);
  return result;
}

}  // namespace cosserat::run
