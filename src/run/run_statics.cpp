#include "cosserat/run/run_statics.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/analysis/column.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/run/grid_resolution.hpp"
#include "cosserat/run/run_quatfd.hpp"
#include "cosserat/robots/tendon_control.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/shooting_exponent.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "anchor_force.hpp"
#include "column_guide_note.hpp"
#include "settle_beside_instability.hpp"
#include "statics_in_pieces.hpp"
#include "foundation_hint.hpp"
#include "stability_warning.hpp"
#include "frame_output.hpp"
#include "node_table.hpp"
#include "tendon_law_limit.hpp"

namespace cosserat::run {
namespace {

/// The summary line. A solve that stopped with iterations to spare (status max_iterations)
/// found no step that lowered its residual: said, so that "1 iterations" does not read as a cap.
std::string StaticSummary(const StaticShootingSummary& s, const RodState& state,
                          const io::Problem& problem) {
  const int max_iterations = problem.solver.max_iterations;
  std::ostringstream line;
  line << "cosserat: " << ToString(s.status) << ", " << s.iterations << " iterations";
  if (s.status == SolveStatus::kMaxIterations && s.iterations < max_iterations)
    line << " (of " << max_iterations << " allowed: no step lowered the residual further)";
  line << ", residual " << std::setprecision(3) << s.residual;
  if (state.size() > 0) {
    const Vec3& tip = state.tip_position_W();
    line << ", tip at [" << std::setprecision(6) << tip.x() << ", " << tip.y() << ", " << tip.z()
         << "] m";
  }
  line << ", " << std::setprecision(3) << s.wall_time_s * 1e3 << " ms";
  return line.str();
}

/// After an SE(3) cantilever solve whose load steps stopped short: what to try. A soft rod bent
/// far by its loads is followed in finer steps on a finer grid (a silicone-soft 1 m rod under
/// gravity fails at 41 nodes and converges at 201), and the quaternion-FD statics follow the
/// same loads by Newton on every node at once.
std::string ContinuationHint(const io::Problem& problem, const StaticShootingSummary& summary) {
  if (summary.status != SolveStatus::kLoadSteppingFailed) return "";
  std::ostringstream hint;
  hint << "cosserat: hint: the load steps stopped short of the full load";
  // Three digits, more near the end (0.99998 would print as 1).
  if (std::isfinite(summary.load_fraction))
    hint << ", at " << std::setprecision(summary.load_fraction > 0.999 ? 7 : 3)
         << summary.load_fraction << " of it";
  hint << " (the shape written is "
          "the last load level reached): a finer grid (rod.nodes, now "
       << problem.nodes
       << ") or \"formulation\": \"quaternion-fd\" may follow the loads to the end\n";
  return hint.str();
}

/// After displacement control whose lengths leave the tensions free in `directions` ways
/// (TendonLengthSummary::free_tension_directions): the tensions are one set of a family.
std::string TensionFamilyNote(int directions) {
  if (directions <= 0) return "";
  return "cosserat: note: the commanded lengths do not fix the tensions: the taut tendons bend "
         "the rod alike, and their tensions can change in " +
         std::to_string(directions) +
         " way(s) with no change of shape; these are one such set (a taut tendon may carry 0 "
         "N), so give tensions where their split matters (co-contraction, stiffness)\n";
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
  if (column.converged())  // its unstable directions (−1: not defined)
    summary.stability_index = solver.StabilityIndexAtUnknowns(problem.base, problem.loads);
  // Past a critical load the loads reach the straight state (a symmetric column) or jump to
  // the one beside a side load's bent path: both unstable. The column settles beside it.
  std::string settled_note;
  int bow_index = -1;  // the bow's unstable directions beside an unsettled column
  if (column.converged() && summary.stability_index > 0 && detail::MaySettle(problem)) {
    const RodState straight = solver.state();
    const Vec6 straight_unknowns = solver.unknowns();
    StaticShootingSummary settled;
    double imperfection = 0.0;
    if (detail::SettleColumn(problem, straight, &solver, &settled, &imperfection, &bow_index)) {
      settled_note = detail::SettledNote(summary.stability_index, imperfection);
      settled.CountWorkOf(summary);
      summary = settled;
    } else {  // back to the straight state: Newton from its unknowns records it again
      summary.CountWorkOf(settled);  // the settling's work counts
      solver.set_unknowns(straight_unknowns);
      solver.Solve(problem.base, problem.loads);
    }
  }
  std::string unjudged;  // a grid too coarse to count unstable directions on
  if (column.converged())
    summary.stability_index =
        detail::JudgedStabilityIndex(problem, solver.state(), summary.stability_index, &unjudged);
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Result result;
  result.json = io::StaticResultToJson(summary, solver.state());
  detail::KeepStaticFrame(problem, solver.state(), options, &result);
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(solver.state());
  result.log = StaticSummary(summary, solver.state(), problem) + " (" + ToString(ends) + ")\n" +
               settled_note + unjudged + detail::GuideTakesTipForceNote(problem, ends);
  result.converged = summary.converged();
  // An equilibrium left unstable: the index says so; where it is not defined, the comparison
  // with the Euler load of the free column does (not on contact surfaces, which hold a column
  // laterally: a bore, a seabed).
  if (result.converged && summary.stability_index != 0) {
    const std::string past_euler =
        problem.loads.contact.count == 0
            ? detail::ColumnPastEulerWarning(ends, problem.rod, solver.state(), bow_index)
            : "";
    result.log += summary.stability_index > 0 && past_euler.empty()
                      ? detail::UnstableWarning(summary, false)
                      : past_euler;
  }
  return result;
}

/// A cantilever or column whose single shot would amplify errors beyond double precision (a
/// stiff contact foundation, a high tension): multiple shooting in pieces it chooses.
Result RunMultipleShootingStatics(const io::Problem& problem, const RunOptions& options,
                                  ColumnEnds ends = ColumnEnds::kClampedFree, int pieces = 0) {
  detail::StaticsInPieces solved =
      detail::SolveStaticsInPieces(problem, ends, problem.base, problem.loads, pieces);
  std::string unjudged;  // a grid too coarse to count unstable directions on
  if (solved.summary.converged())
    solved.summary.stability_index = detail::JudgedStabilityIndex(
        problem, solved.state, solved.summary.stability_index, &unjudged);
  std::string settled_note;
  if (ends == ColumnEnds::kClampedFree && solved.summary.converged() &&
      solved.summary.stability_index > 0 && detail::MaySettle(problem)) {
    detail::StaticsInPieces settled;
    double imperfection = 0.0;
    if (detail::SettleInPieces(problem, solved.state, solved.summary.stability_index,
                               solved.pieces, &settled, &imperfection)) {
      settled_note = detail::SettledNote(solved.summary.stability_index, imperfection);
      settled.summary.CountWorkOf(solved.summary);
      solved = settled;
    } else {
      solved.summary.CountWorkOf(settled.summary);  // the settling's work counts
    }
  }
  const StaticShootingSummary& summary = solved.summary;
  Result result;
  result.json = io::StaticResultToJson(summary, solved.state);
  detail::KeepStaticFrame(problem, solved.state, options, &result);
  result.json["shooting_segments"] = solved.pieces;
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(solved.state);
  const std::string column =
      ends == ColumnEnds::kClampedFree ? "" : ToString(ends) + std::string(", ");
  result.log = StaticSummary(summary, solved.state, problem) + " (" + column +
               std::to_string(solved.pieces) + " shooting pieces)\n" + settled_note +
               FramesLeftRotationsLine(solved.state, problem.rod.length) +
               ContinuationHint(problem, summary) + detail::UnstableWarning(summary, false) +
               unjudged + detail::GuideTakesTipForceNote(problem, ends);
  if (summary.converged() && summary.stability_index < 0 && unjudged.empty())
    result.log += detail::UnjudgedCompressionNote(
        problem.rod, solved.state,
        LoadsAreConservative(problem.loads)
            ? "past the Euler load of a free pinned column, and its stability is not judged (the "
              "count of its unstable directions could not be formed: a grid too coarse for its "
              "shape, or a torque held by a pin)"
            : "past the Euler load of a free pinned column, and its stability is not judged (its "
              "loads are not conservative: a follower or a tip moment, drag)");
  result.converged = summary.converged();
  return result;
}

/// After an SE(3) solve of a held rod that failed: its shot (RK4 on the grid) follows the bending
/// boundary layers at the anchors, of length sqrt(EI/T), only while k h = h sqrt(T/EI) stays
/// below RK4's stability limit on a decaying exponential, 2.8 (a 200 m stay cable at 4 MN fails
/// at k h = 4.5 and converges at k h = 2.2 and below). The hint names the nodes for k h = 2.
std::string BoundaryLayerHint(const io::Problem& problem, const RodState& guess) {
  const SectionProperties p = problem.rod.section->At(0.0, Actuation{});
  const double ei = p.min_bending_stiffness();  // N·m²
  const double k = std::sqrt(guess.MaxForce() / ei), h = problem.rod.length / (problem.nodes - 1);
  if (k * h <= 2.0) return "";
  std::ostringstream hint;
  hint << "cosserat: hint: the grid spacing " << std::setprecision(3) << h
       << " m is coarse for the bending boundary layers at the anchors, sqrt(EI/T) = " << 1.0 / k
       << " m, which the SE(3) shot resolves at spacings up to about twice that: try rod.nodes >= "
       << static_cast<long>(std::ceil(problem.rod.length * k / 2.0)) + 1
       << ", or \"formulation\": \"quaternion-fd\"\n";
  return hint.str();
}

/// After an SE(3) solve that failed: a contact surface's foundation adds decaying oscillations of
/// rate √2/ℓ to the shot, ℓ its foundation length, which RK4 on the grid follows only while
/// √2 h/ℓ stays below its stability limit of about 2.8 (a riser on a sea bed with ℓ = 3 m fails at
/// h = 7 m and converges at 5.8 m and below). The hint names the nodes for h = ℓ.
std::string ShotFoundationHint(const io::Problem& problem) {
  return detail::FoundationHint(problem, 1.0,
                                "which the SE(3) shot resolves at spacings up to about that", "",
                                ", or \"formulation\": \"quaternion-fd\"");
}

/// A rod held at both ends ("anchored") on the SE(3) path: multiple shooting from the
/// quaternion-FD equilibrium on the same grid, a state through both anchors with its internal
/// forces (the SE(3) rest shape does not meet the tip's anchor, and a sagging cable has no
/// unloaded shape to follow its loads from). The SE(3) solve then satisfies its own discrete
/// equations; the two differ by their discretisation errors.
Result RunAnchoredStatics(const io::Problem& problem, const RunOptions& options) {
  quatfd::QuatFdModel model = MakeQuatFdModel(problem);
  RodState guess;
  const quatfd::QuatFdStaticsSummary start = SolveQuatFdEquilibrium(problem, &model, &guess);

  StaticMultipleShootingOptions opt;
  opt.tolerance = problem.solver.tolerance;
  opt.max_iterations = problem.solver.max_iterations;
  opt.base_pinned = !problem.anchor.base_clamped;
  opt.tip_pinned = true;
  opt.tip_position_W = problem.anchor.position;
  opt.tip_clamped = problem.anchor.tip_clamped;
  opt.tip_rotation_W = problem.anchor.rotation;
  StaticMultipleShootingSolver solver(problem.rod, problem.nodes, opt);
  StaticShootingSummary summary;
  summary.status = start.status;
  summary.residual = start.residual;
  summary.iterations = start.iterations;
  // A pinned base's twist reference, as the quaternion-FD model takes it: the base frame turned
  // by the least rotation onto the chord (the start's first frame then has no third exponential
  // coordinate against it).
  lie::SE3 base = problem.base;
  if (opt.base_pinned) base.R = lie::SO3TurnedOnto(base.R, problem.anchor.position - base.p);
  if (start.converged()) summary = solver.SolveFrom(base, problem.loads, guess);
  const RodState& state = start.converged() ? solver.state() : guess;

  Result result;
  result.json = io::StaticResultToJson(summary, state);
  detail::KeepStaticFrame(problem, state, options, &result);
  result.json["shooting_segments"] = solver.pieces();
  // The force the tip's anchor exerts on the rod (N, world): the top tension of a cable.
  const Vec3 f = state.rotation_WB.back() * state.wrench_B.back().tail<3>();
  result.json["anchor_force"] = {f.x(), f.y(), f.z()};
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(state);
  std::ostringstream log;
  if (!start.converged())
    log << "cosserat: the start of the SE(3) solve, the quaternion-FD equilibrium on the same "
           "grid, did not converge ("
        << ToString(start.status) << ", residual " << std::setprecision(3) << start.residual
        << "); try \"formulation\": \"quaternion-fd\" for its diagnosis\n";
  log << StaticSummary(summary, state, problem) << " (" << solver.pieces() << " shooting pieces), "
      << detail::AnchorForceText(state) << '\n';
  if (start.converged() && !summary.converged())
    log << BoundaryLayerHint(problem, guess) << ShotFoundationHint(problem);
  if (start.converged() && summary.converged())
    log << detail::AnchoredCompressionNote(problem.rod, state);
  result.log = log.str();
  result.converged = start.converged() && summary.converged();
  return result;
}

/// A cantilever, robots included, in one shot from the clamp.
/// An unstable equilibrium of a symmetric problem: the stable one beside it, solved by *beside
/// (left empty when not reached). *summary becomes its solve, the settling's work counted either
/// way. Returns the log's note on it, empty when not settled.
std::string SettleBesideSingleShot(const io::Problem& problem, const StaticShootingSolver& first,
                                   const Actuation& actuation, StaticShootingSummary* summary,
                                   std::optional<StaticShootingSolver>* beside) {
  if (!(summary->converged() && summary->stability_index > 0 && detail::MaySettle(problem)))
    return "";
  beside->emplace(problem.rod, problem.nodes, StaticOptions(problem), actuation);
  StaticShootingSummary settled;
  double imperfection = 0.0;
  if (!detail::SettleSingleShot(problem, first.state(), summary->stability_index, &**beside,
                                &settled, &imperfection)) {
    summary->CountWorkOf(settled);
    beside->reset();
    return "";
  }
  const std::string note = detail::SettledNote(summary->stability_index, imperfection);
  settled.CountWorkOf(*summary);
  *summary = settled;
  return note;
}

Result RunSingleShotStatics(const io::Problem& problem, const RunOptions& options) {
  Actuation actuation = problem.robot.actuation;
  StaticShootingSolver first(problem.rod, problem.nodes, StaticOptions(problem), actuation);
  StaticShootingSummary summary = first.Solve(problem.base, problem.loads);
  std::string unjudged;  // a grid too coarse to count unstable directions on
  if (summary.converged())
    summary.stability_index =
        detail::JudgedStabilityIndex(problem, first.state(), summary.stability_index, &unjudged);
  std::optional<StaticShootingSolver> beside;
  const std::string settled_note =
      SettleBesideSingleShot(problem, first, actuation, &summary, &beside);
  StaticShootingSolver& solver = beside ? *beside : first;
  std::array<bool, Actuation::kMaxTendons> slack{};
  for (int i = 0; i < Actuation::kMaxTendons; ++i)
    slack[i] = actuation.tendon_tension[i] == 0.0;  // force control: slack means no tension
  double length_error = -1.0;  // displacement control: the largest |ℓ − ℓ_cmd|, m
  int free_tension_directions = 0;  // displacement control: the tensions' family's dimension
  if (problem.robot.tendon_lengths && summary.converged()) {
    // Displacement control: the tensions that give the commanded tendon lengths.
    const auto t0 = std::chrono::steady_clock::now();
    const TendonLengthSummary t = SolveTendonLengths(solver, problem.base, problem.loads,
                                                     *problem.robot.tendon_lengths, &actuation);
    summary.status = t.status;
    summary.iterations += t.iterations;
    summary.shots += t.shots;
    if (t.solves > 0) summary.residual = t.residual;  // the last equilibrium's, not the first
    summary.wall_time_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    slack = t.slack;
    length_error = t.length_error;
    free_tension_directions = t.free_tension_directions;
  }
  Result result;
  result.json = io::StaticResultToJson(summary, solver.state());
  detail::KeepStaticFrame(problem, solver.state(), options, &result);
  if (problem.has_robot) {
    const int count = solver.tendon_count();
    nlohmann::ordered_json robot;
    robot["kind"] = io::ToString(problem.robot.kind);
    robot["tendon_tension"] = std::vector<double>(actuation.tendon_tension.begin(),
                                                  actuation.tendon_tension.begin() + count);
    robot["tendon_length"] = std::vector<double>(solver.tendon_lengths().begin(),
                                                 solver.tendon_lengths().begin() + count);
    robot["tendon_slack"] = std::vector<bool>(slack.begin(), slack.begin() + count);
    if (length_error >= 0.0) robot["tendon_length_error"] = length_error;
    if (length_error >= 0.0 && summary.converged())
      robot["free_tension_directions"] = free_tension_directions;
    if (!problem.rod.chambers.empty())
      robot["chamber_pressure"] =
          std::vector<double>(actuation.chamber_pressure.begin(),
                              actuation.chamber_pressure.begin() + problem.rod.chambers.size());
    result.json["robot"] = robot;
  }
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(solver.state());
  // A shot that ran away on a coarse grid is not the tendon law's failure (the grid check says
  // what is).
  const RodState& state = solver.state();
  result.log = StaticSummary(summary, state, problem) + '\n' + settled_note +
               (state.RanAway() ? FramesLeftRotationsLine(state, problem.rod.length)
                                : TendonLawHint(problem, actuation, summary.status)) +
               (summary.converged() ? TensionFamilyNote(free_tension_directions) : "");
  if (!problem.has_robot) result.log += ContinuationHint(problem, summary);
  const bool on_surfaces = problem.loads.contact.count > 0;
  result.log += detail::UnstableWarning(summary, true, on_surfaces) + unjudged;
  result.converged = summary.converged();
  return result;
}

}  // namespace

Result RunStatics(const io::Problem& problem, const RunOptions& options) {
  if (problem.boundary == io::Boundary::kAnchored) return RunAnchoredStatics(problem, options);
  ColumnEnds ends = ColumnEnds::kClampedFree;
  const bool column =
      problem.boundary != io::Boundary::kCantilever && ToColumnEnds(problem.boundary, &ends);
  const bool pieces_possible =
      !problem.has_robot && problem.rod.tendons.empty() && problem.rod.chambers.empty();
  const double exponent = StaticShootingExponent(problem.rod, problem.loads);
  // Beyond an exponent of 10 a single shot loses the branch (a column at L sqrt(T/EI) = 19
  // converged, looped, onto an equilibrium far from the straight one) or the precision.
  if (pieces_possible && exponent > 10.0)
    return RunMultipleShootingStatics(problem, options, ends);
  // A column on contact surfaces: the penalty's smoothing ramp is thin (1e-3 of the diameter), so
  // the residual's Jacobian jumps as nodes cross it, and the column solver's damped Newton stalls
  // (a pipe pressed in a bore: 6 000 iterations, 5 s). Multiple shooting, with its stiffness
  // continuation and Levenberg–Marquardt, took 20 to 60 iterations in two pieces.
  const int split_pieces =
      std::min(problem.nodes - 1, std::max(2, SuggestedShootingSegments(exponent)));
  if (pieces_possible && column && problem.loads.contact.count > 0)
    return RunMultipleShootingStatics(problem, options, ends, split_pieces);
  Result single = column ? RunColumnStatics(problem, ends, options)
                         : RunSingleShotStatics(problem, options);
  if (single.converged || !pieces_possible) return single;
  // The single shot failed below that exponent (a rod on a foundation near it, a column in a
  // bore): the rod in pieces, at least two, as the dynamics stepper adds pieces before it gives
  // up. The single shot's result stands if they fail too.
  const int pieces = split_pieces;
  Result split = RunMultipleShootingStatics(problem, options, ends, pieces);
  if (!split.converged) return single;
  split.log += "cosserat: note: one shot from the clamp did not converge (" +
               single.json.value("status", std::string()) + "); the rod was shot in " +
               std::to_string(pieces) + " pieces\n";
  return split;
}

}  // namespace cosserat::run
