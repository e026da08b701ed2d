#include "cosserat/run/run_quatfd.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <limits>
#include <iomanip>
#include <sstream>

#include "cosserat/io/result_writer.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/quatfd/radau.hpp"
#include "cosserat/run/grid_resolution.hpp"
#include "cosserat/run/solver_options.hpp"
#include "settle_beside_instability.hpp"
#include "anchor_force.hpp"
#include "contact_report.hpp"
#include "foundation_hint.hpp"
#include "frame_output.hpp"
#include "node_table.hpp"
#include "obstacle_core_watch.hpp"
#include "quatfd_stability.hpp"
#include "stability_warning.hpp"

namespace cosserat::run {
namespace {

using Clock = std::chrono::steady_clock;

StaticShootingSummary AsSummary(const quatfd::QuatFdStaticsSummary& s) {
  StaticShootingSummary out;
  out.status = s.status;
  out.iterations = s.iterations;
  out.load_steps = s.load_steps;
  out.residual = s.residual;
  out.wall_time_s = s.wall_time_s;
  return out;
}

/// "<what> at [x, y, z] m" (world, 6 digits).
std::string PositionText(const char* what, const Vec3& p) {
  std::ostringstream line;
  line << what << " at [" << std::setprecision(6) << p.x() << ", " << p.y() << ", " << p.z()
       << "] m";
  return line.str();
}

std::string TipText(const RodState& state) { return PositionText("tip", state.tip_position_W()); }

/// After a static solve that failed: when the grid spacing exceeds half a contact surface's
/// foundation length, the grid hardly resolves the contact (a few vertices carry a patch's load).
std::string ContactGridHint(const io::Problem& problem) {
  return detail::FoundationHint(problem, 0.5, "over which the rod settles into it",
                                "a spacing of half that, ", "");
}

/// After a converged solve of a rod on a contact surface: where it bends most (a riser's
/// touchdown), the curvature decays over the bending length sqrt(EI/T) of the axial force T
/// there, and a grid spacing h beyond it under-resolves the peak: a riser on the seabed (350 m,
/// sqrt(EI/T) = 10 m) gave a peak bending stress 1 % low at h = 10 m, 19 % at 35 m, 32 % at
/// 88 m, with no word (about second order: some 2 % at 1.5). From k h = 1.5 on
/// (k = sqrt(T/EI)), a warning names the nodes for k h = 0.5.
std::string BendingPeakGridWarning(const io::Problem& problem, const RodState& state) {
  if (problem.loads.contact.count == 0 || state.size() < 3) return "";
  // The bending of the rest shape's curvature away (κ − κ*), which the moment follows.
  auto bending = [&](int i) {
    return (state.strain[i].head<2>() - problem.rod.RestStrainAt(state.s[i]).head<2>()).norm();
  };
  int peak = 0;
  for (int i = 1; i < state.size(); ++i)
    if (bending(i) > bending(peak)) peak = i;
  if (peak == 0 || peak == state.size() - 1 || bending(peak) == 0.0)
    return "";  // at an end: a clamp's moment, which ClampedEndGridWarning judges
  const double ei = problem.rod.section->At(state.s[peak], problem.robot.actuation)
                        .min_bending_stiffness();  // N·m²
  const double k = std::sqrt(std::abs(state.wrench_B[peak](5)) / ei);  // 1/m
  const double h = std::max(state.s[peak + 1] - state.s[peak], state.s[peak] - state.s[peak - 1]);
  if (!(k * h > 1.5)) return "";
  std::ostringstream warning;
  warning << std::setprecision(3) << "cosserat: warning: the rod bends most at s = "
          << state.s[peak] << " m, where its curvature decays over sqrt(EI/T) = " << 1.0 / k
          << " m, and the grid spacing is " << h
          << " m: the peak's curvature and bending stress come out low (a riser's touchdown: "
             "19 % at a spacing of 3.5 sqrt(EI/T), 1 % at 1); rod.nodes >= "
          << static_cast<long>(std::ceil(problem.rod.length * k / 0.5)) + 1 << "\n";
  return warning.str();
}

/// After a failed solve of a slack anchored line with no net distributed load (its weight
/// buoyed off by the fluid, or no gravity): every shape of its length between the anchors
/// balances, and Newton has no one equilibrium to converge to.
std::string SlackLineHint(const io::Problem& problem) {
  if (problem.boundary != io::Boundary::kAnchored || problem.loads.contact.count > 0) return "";
  const double L = problem.rod.length, chord = (problem.anchor.position - problem.base.p).norm();
  if (!(chord < (1.0 - 1e-6) * L)) return "";
  const SectionProperties p = problem.rod.section->At(0.5 * L, problem.robot.actuation);
  const LoadSite site{0.5 * L, 1.0, p.mass(3, 3), p.outer_diameter};
  const double net = TotalDistributedForce_W(problem.loads, site).norm();  // N/m
  const double weight = p.mass(3, 3) * std::max(problem.loads.gravity_W.norm(), 9.81);  // N/m
  if (net > 1e-3 * weight) return "";
  std::ostringstream hint;
  hint << std::setprecision(4) << "cosserat: hint: the line is slack (" << L
       << " m between anchors " << chord
       << " m apart) and nothing pulls it sideways: no net load acts on it (its weight "
          "buoyed off by the fluid, or no gravity), so it balances in a whole family of shapes "
          "of its length between the anchors and none is the answer; give it a net weight "
          "(its density against the fluid's), a current, or anchors as far apart as its "
          "length\n";
  return hint.str();
}

/// After a failed solve of a slack anchored line hanging almost straight up and down: its
/// catenary turns at its lowest point with a radius of a = H/w, its parameter (Irvine 1981),
/// found from 2a sinh(l/2a) = sqrt(L² − h²) (l across, h up the net load's line), and a grid
/// spacing above a cannot follow the turn (a 110 m line between anchors 100 m up and 1 m
/// across: a = 8 cm against 0.28 m).
std::string SteepLineHint(const io::Problem& problem) {
  if (problem.boundary != io::Boundary::kAnchored || problem.loads.contact.count > 0) return "";
  const double L = problem.rod.length;
  const Vec3 chord = problem.anchor.position - problem.base.p;
  const SectionProperties p = problem.rod.section->At(0.5 * L, problem.robot.actuation);
  const Vec3 net = TotalDistributedForce_W(
      problem.loads, LoadSite{0.5 * L, 1.0, p.mass(3, 3), p.outer_diameter});  // N/m
  if (!(net.norm() > 0.0) || !(chord.norm() < L)) return "";
  const Vec3 up = -net.normalized();
  const double h = chord.dot(up), l = (chord - h * up).norm(), sag = std::sqrt(L * L - h * h);
  if (!(l > 0.0)) return "";
  auto span = [&](double a) {  // 2a sinh(l/2a), falling from ∞ (a → 0) to l (a → ∞)
    const double x = l / (2.0 * a);
    return x > 700.0 ? std::numeric_limits<double>::infinity() : 2.0 * a * std::sinh(x);
  };
  double lo = 1e-12 * L, hi = 1e12 * L;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (span(mid) > sag ? lo : hi) = mid;
  }
  const double a = std::sqrt(lo * hi), spacing = L / (problem.nodes - 1);
  if (!(spacing > a)) return "";
  std::ostringstream hint;
  hint << std::setprecision(3) << "cosserat: hint: the line hangs almost straight ("
       << h << " m along its weight, " << l << " m across, " << L
       << " m long): its catenary turns at its lowest point with a radius of about H/w = " << a
       << " m, below the grid spacing " << spacing
       << " m, which cannot follow the turn, and Newton from that tight loop often stalls; "
          "a spacing of a/2 (rod.nodes >= "
       << static_cast<long>(std::ceil(2.0 * L / a)) + 1
       << ") or anchors farther apart may let it converge\n";
  return hint.str();
}

}  // namespace

quatfd::QuatFdModel MakeQuatFdModel(const io::Problem& problem) {
  quatfd::QuatFdModel model(problem.rod, problem.base, QuatFdModelOptions(problem),
                            problem.robot.actuation);  // chamber pressures (statics)
  model.set_loads(problem.loads);
  return model;
}

// The clamp moment on quaternion FD comes out low by about 12 (h/ℓ)² %, ℓ = sqrt(EI/T) the
// bending boundary layer, while h < ℓ (a stay cable: 0.6 % at h = 0.23 ℓ, 2.4 % at 0.45; a
// tensioned riser: 0.8 % at 0.25, 6.5 % at 0.75), and by 20 % at 1.5 ℓ and 59 % at 4.5 ℓ. From
// h = 0.3 ℓ (1 %) on, a warning gives h/ℓ and names the nodes for 0.25 ℓ. The modes about that
// equilibrium miss a share of the clamps' stiffening, ℓ/L of each frequency per clamped end
// (2ℓ/L for both: Mehrabi & Tabatabai 1998), about 0.13 h/ℓ of it (a stay clamped at both
// ends: 61 % at 4.5 ℓ, 15 % at 1.1, 4 % at 0.45; at one end 0.067 % at 4.5 ℓ, stated 0.065 %).
std::string ClampedEndGridWarning(const io::Problem& problem, const RodState& state) {
  if (problem.boundary != io::Boundary::kAnchored ||
      !(problem.anchor.base_clamped || problem.anchor.tip_clamped))
    return "";
  const double ei = problem.rod.section->At(0.0, Actuation{}).min_bending_stiffness();  // N·m²
  const double ell = std::sqrt(ei / state.MaxForce());  // m
  const double h = problem.rod.length / (problem.nodes - 1);
  const double ratio = h / ell;
  if (!(ratio > 0.3)) return "";
  std::ostringstream warning;
  warning << std::setprecision(3) << "cosserat: warning: the grid spacing " << h << " m is "
          << ratio << " times the bending boundary layer at the clamped anchor, sqrt(EI/T) = "
          << ell << " m: the clamp's moment comes out low, ";
  if (ratio <= 1.0)
    warning << "by about 12 (h/sqrt(EI/T))² % = " << 12.0 * ratio * ratio << " %";
  else
    warning << "by over 12 % (20 % at 1.5 times sqrt(EI/T), 59 % at 4.5; docs/cables.md)";
  const int clamps = problem.anchor.base_clamped + problem.anchor.tip_clamped;
  if (problem.analysis == io::Analysis::kModes)
    warning << ", and each frequency misses about "
            << std::min(1.0, 0.13 * ratio) * 100 * clamps * ell / problem.rod.length
            << " % of itself (a share of the clamps' stiffening, sqrt(EI/T)/L for each)";
  const long nodes = static_cast<long>(std::ceil(problem.rod.length / (0.25 * ell))) + 1;
  warning << "; rod.nodes >= " << nodes << " keeps the moment within 1 %\n";
  return warning.str();
}

quatfd::QuatFdStaticsSummary SolveQuatFdEquilibrium(const io::Problem& problem,
                                                    quatfd::QuatFdModel* model, RodState* state,
                                                    Eigen::VectorXd* q_out) {
  Eigen::VectorXd q(model->size()), v(model->size());
  model->RestState(q, v);
  const quatfd::QuatFdStaticsSummary s =
      quatfd::SolveStatics(model, problem.loads, q, QuatFdStaticOptions(problem));
  model->ToRodState(q, v, state);
  if (q_out) *q_out = q;
  return s;
}

namespace {

/// The continuation from the rest shape, for a direct solve that landed on an unstable
/// equilibrium: a column pressed past its Euler load, left straight against the lateral load
/// that bends it, where the loaded path leads to the bent, stable shape. Kept when it is less
/// unstable; the counts of both solves' iterations and wall times add up either way.
void FollowLoadedPathIfUnstable(const io::Problem& problem, quatfd::QuatFdModel* model,
                                quatfd::QuatFdStaticsSummary* s, StaticShootingSummary* summary,
                                RodState* state, Eigen::VectorXd* q) {
  const quatfd::QuatFdStaticsOptions options = QuatFdLoadedPathOptions(problem);
  if (summary->stability_index <= 0 || !options.load_stepping) return;
  Eigen::VectorXd q_path(model->size()), v = Eigen::VectorXd::Zero(model->size());
  model->RestState(q_path, v);
  quatfd::QuatFdStaticsSummary path = quatfd::SolveStatics(model, problem.loads, q_path, options);
  path.iterations += s->iterations;
  path.wall_time_s += s->wall_time_s;
  auto keep_the_direct_solve = [&] {  // with the discarded path's work counted
    s->iterations = summary->iterations = path.iterations;
    s->wall_time_s = summary->wall_time_s = path.wall_time_s;
  };
  if (!path.converged()) return keep_the_direct_solve();
  RodState path_state;
  model->ToRodState(q_path, v, &path_state);
  const int index = detail::QuatFdStabilityIndex(problem, q_path, path_state);
  if (index >= summary->stability_index) return keep_the_direct_solve();
  *s = path;
  *summary = AsSummary(path);
  summary->stability_index = index;
  *state = path_state;
  *q = q_path;
}

}  // namespace

Result RunQuatFdStatics(const io::Problem& problem, const RunOptions& options) {
  quatfd::QuatFdModel model = MakeQuatFdModel(problem);
  RodState state;
  Eigen::VectorXd q;
  quatfd::QuatFdStaticsSummary s = SolveQuatFdEquilibrium(problem, &model, &state, &q);
  StaticShootingSummary summary = AsSummary(s);
  if (s.converged()) summary.stability_index = detail::QuatFdStabilityIndex(problem, q, state);
  FollowLoadedPathIfUnstable(problem, &model, &s, &summary, &state, &q);
  std::string settled_note;
  if (summary.stability_index > 0 && detail::MaySettle(problem)) {
    int settled = 0;
    double imperfection = 0.0;
    quatfd::QuatFdStaticsSummary s2;
    if (detail::SettleQuatFd(problem, state, summary.stability_index, &model, &q, &state, &s2,
                             &settled, &imperfection)) {
      settled_note = detail::SettledNote(summary.stability_index, imperfection);
      s2.iterations += s.iterations;
      s2.wall_time_s += s.wall_time_s;
      s = s2;
      summary = AsSummary(s);
      summary.stability_index = settled;
    } else {  // the settling's work counts
      summary.iterations += s2.iterations;
      summary.wall_time_s += s2.wall_time_s;
    }
  }
  Result result;
  result.json = io::StaticResultToJson(summary, state);
  detail::KeepStaticFrame(problem, state, options, &result);
  if (problem.has_robot) {  // a pneumatic robot (tendons run on the SE(3) path): its pressures
    nlohmann::ordered_json robot;
    robot["kind"] = io::ToString(problem.robot.kind);
    const Actuation& a = problem.robot.actuation;
    robot["chamber_pressure"] = std::vector<double>(
        a.chamber_pressure.begin(), a.chamber_pressure.begin() + problem.rod.chambers.size());
    result.json["robot"] = robot;
  }
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(state);
  std::ostringstream log;
  log << "cosserat: " << ToString(s.status) << " (quaternion-fd), " << summary.iterations
      << " iterations, residual " << std::setprecision(3) << s.residual << ", ";
  if (problem.boundary == io::Boundary::kAnchored) {
    // The force the tip's anchor exerts on the rod (N, world): the top tension of a cable.
    const Vec3 f = state.rotation_WB.back() * state.wrench_B.back().tail<3>();
    result.json["anchor_force"] = {f.x(), f.y(), f.z()};
    log << detail::AnchorForceText(state);
  } else {
    log << TipText(state);
  }
  log << ", " << std::setprecision(3) << summary.wall_time_s * 1e3 << " ms\n";
  if (!s.converged())
    log << ContactGridHint(problem) << SlackLineHint(problem) << SteepLineHint(problem);
  if (s.converged())
    log << settled_note << ClampedEndGridWarning(problem, state)
        << BendingPeakGridWarning(problem, state)
        << detail::UnstableWarning(summary, true, problem.loads.contact.count > 0);
  if (s.converged() && problem.boundary == io::Boundary::kAnchored)
    log << detail::AnchoredCompressionNote(problem.rod, state);
  result.log = log.str();
  result.converged = s.converged();
  return result;
}

namespace {

/// What the Radau run reports besides io::DynamicRun.
struct RadauOutcome {
  quatfd::IntegratorStatus status = quatfd::IntegratorStatus::kNotRun;
  double last_dt = 0.0;  ///< s, the last accepted step
};

/// Integrates (q, v) from t = 0 to the problem's duration with Radau IIA, calling record(t) at
/// every output interval, and fills run's step counts, times, status and final energy.
/// `progress` (t, duration), when set, also follows every accepted step: an output interval may
/// take minutes, and a Python caller's Ctrl-C is asked there.
template <class Record>
RadauOutcome IntegrateRadau(quatfd::QuatFdModel& model, const io::Problem::Dynamics& d,
                            Eigen::VectorXd& q, Eigen::VectorXd& v, const Record& record,
                            const std::function<void(double, double)>& progress,
                            detail::ObstacleCoreWatch* obstacles, io::DynamicRun* run) {
  RadauOutcome outcome;
  quatfd::IntegratorOptions io_opt;
  io_opt.initial_dt = d.dt;
  io_opt.rel_tol = io_opt.abs_tol = d.integrator_tolerance;
  io_opt.max_steps = d.integrator_max_steps;
  // After every accepted step: the progress, and the vertices' positions for the obstacle watch.
  const quatfd::RadauIntegrator* stepping = nullptr;
  std::vector<Vec3> vertices(model.layout().segments + 1);
  if (progress || obstacles)
    io_opt.after_step = [&](double t) {
      if (obstacles && stepping) {
        for (std::size_t i = 0; i < vertices.size(); ++i)
          vertices[i] = stepping->state().segment<3>(quatfd::QuatFdLayout::X(static_cast<int>(i)));
        obstacles->Observe(t, vertices);
      }
      if (progress) progress(t, d.duration);
    };
  // The implicit Radau IIA integrator (docs/quatfd.md): like SDIRK4 its step map stays stable
  // at the steps the error control asks for, where the Rosenbrock integrator's does not, and
  // with stage order 3 it needs fewer steps than SDIRK4 on both benchmarks (BENCHMARKS.md).
  quatfd::RadauIntegrator integrator(model, io_opt);
  stepping = &integrator;
  // Frames every output_interval, and the end of the run when it falls between two (a frame
  // within 1e-9 of an interval of the end is the end's).
  const double ratio = d.duration / d.output_interval;
  const int whole = static_cast<int>(std::floor(ratio + 1e-9));
  const int intervals = std::max(1, whole + (ratio - whole > 1e-9 ? 1 : 0));
  const auto loop_start = Clock::now();
  double t = 0.0;
  for (int k = 1; k <= intervals; ++k) {
    const double t_end = k == intervals ? d.duration : k * d.output_interval;
    const long steps_before = integrator.stats().steps;
    const auto t0 = Clock::now();
    outcome.status = integrator.Advance(t_end, &t, q, v);
    const long steps = integrator.stats().steps - steps_before;
    if (steps > 0)
      run->step_time_s.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / steps);
    if (outcome.status != quatfd::IntegratorStatus::kOk) {
      // Divergence (step-size underflow) or the step cap: reported as a failed run.
      run->status = outcome.status == quatfd::IntegratorStatus::kMaxSteps
                        ? SolveStatus::kMaxIterations
                        : SolveStatus::kNonFinite;
      run->failed_at_t = t;
      break;
    }
    record(t);
  }
  run->stepping_wall_time_s = std::chrono::duration<double>(Clock::now() - loop_start).count();
  run->steps = static_cast<int>(integrator.stats().steps);
  run->halved_steps = static_cast<int>(integrator.stats().rejected);  // rejected steps
  run->simulated_time_s = t;
  outcome.last_dt = integrator.stats().last_dt;
  if (run->frame_t.back() != t) record(t);
  const quatfd::QuatFdEnergy e = model.Energy(q, v);
  run->energy.kinetic = e.kinetic;
  run->energy.elastic = e.elastic;
  run->energy.potential = e.potential;
  return outcome;
}

/// Where Radau's steps were short enough to follow the model's fastest motion, the rotation of
/// the sections against their shear, ω = sqrt(κGA/ρI) (a sudden load rings it, and undamped it
/// rings on: a stiff wire under a step moment took 53 000 steps per 2 ms), over many steps: a
/// note that says so and what damps it; empty otherwise.
std::string RingingNote(const io::Problem& problem, const io::DynamicRun& run) {
  if (run.steps < 10000 || !(run.simulated_time_s > 0) || !problem.rod.section) return "";
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double omega = std::sqrt(std::min(p.stiffness(3, 3), p.stiffness(4, 4)) /
                                 std::max(p.mass(0, 0), p.mass(1, 1)));  // rad/s
  const double step = run.simulated_time_s / run.steps;                  // s, the mean
  if (!(omega * step < 2.0)) return "";
  std::ostringstream note;
  note << std::setprecision(3) << "cosserat: note: Radau's steps averaged " << step
       << " s, short enough to follow the sections' rotation against their shear, sqrt(κGA/ρI) "
       << "= " << omega / (2 * M_PI) << " Hz, the model's fastest motion: a sudden load rings "
       << "it and, undamped, it rings on. Damping on shear and extension "
       << "(rod.material.damping; docs/quatfd.md, \"Soft rods\") lets the steps pass over it, "
       << "at the cost of that motion\n";
  return note.str();
}

/// The summary line of a dynamics run, and the hint for a run stopped by the step cap.
std::string DynamicsLog(const io::DynamicRun& run, const RadauOutcome& radau,
                        const io::Problem::Dynamics& d, const RodState& state) {
  std::ostringstream log;
  log << "cosserat: " << ToString(run.status) << " (quaternion-fd";
  if (run.initial_state_ok) log << ", radau: " << quatfd::ToString(radau.status);
  log << "), " << run.steps << " steps, " << run.halved_steps << " rejected, "
      << std::setprecision(6) << run.simulated_time_s << " s simulated in " << std::setprecision(3)
      << run.wall_time_s << " s, "
      << (run.frame_midspan.empty()
              ? TipText(state)
              : PositionText("mid-span", state.position_W[state.size() / 2]))  // a held rod's
      << '\n';
  if (radau.status == quatfd::IntegratorStatus::kMaxSteps)
    log << "cosserat: hint: Radau took dynamics.integrator_max_steps (" << d.integrator_max_steps
        << ") steps within one output interval, the last of " << std::setprecision(3)
        << radau.last_dt << " s: a load the rod cannot carry, or a "
        << "run that needs a larger integrator_max_steps or a shorter output_interval\n";
  return log.str();
}

/// The grid check statics make, on the equilibrium a run starts from. A start the grid cannot
/// resolve is no start: a 1000 m riser hung from a vessel straight above its well, compressed
/// 91 % on 200 nodes, took Radau's steps down to 1.4e-6 s, 0.8 ms each, about 14 min per output
/// frame before the step cap stopped it. Its status (under_resolved, or non_finite for a shape
/// that ran away) and the check's words; kConverged and nothing where the start holds.
SolveStatus StartOnTheGrid(const io::Problem& problem, const RodState& start, std::string* log) {
  StaticShootingSummary summary;
  summary.status = SolveStatus::kConverged;
  Result check;
  check.json = io::StaticResultToJson(summary, start);
  check.converged = true;
  CheckGridResolution(problem, &check);  // as for a run's final state
  if (check.converged) return SolveStatus::kConverged;
  *log = "cosserat: the equilibrium the run starts from is not resolved, so it is not stepped "
         "from:\n" + check.log;
  return check.json["status"] == ToString(SolveStatus::kNonFinite) ? SolveStatus::kNonFinite
                                                                    : SolveStatus::kUnderResolved;
}

}  // namespace

Result RunQuatFdDynamics(const io::Problem& problem, const RunOptions& options) {
  const io::Problem::Dynamics& d = problem.dynamics;
  const auto start = Clock::now();
  quatfd::QuatFdModel model = MakeQuatFdModel(problem);
  const int n = model.size();
  Eigen::VectorXd q(n), v(n);
  // A held line's first guess hangs in the loads the model has: the initial ones, which the
  // equilibrium is solved under (a cable let go from a side load is out of reach of a guess
  // hanging in the later loads).
  const StaticLoads& initial_loads = d.initial_loads.value_or(problem.loads);
  model.set_loads(initial_loads);
  model.RestState(q, v);
  io::DynamicRun run;
  const quatfd::QuatFdStaticsSummary init =
      quatfd::SolveStatics(&model, initial_loads, q, QuatFdStaticOptions(problem));
  run.iterations = init.iterations;
  run.residual = init.residual;
  run.initial_state_ok = init.converged();
  run.status = init.status;
  run.report_anchor_force = problem.boundary == io::Boundary::kAnchored;
  run.report_touchdown = run.report_anchor_force && problem.loads.contact.count > 0;
  RodState state;
  model.ToRodState(q, v, &state);
  std::string start_log;
  if (run.initial_state_ok) {
    const SolveStatus start = StartOnTheGrid(problem, state, &start_log);
    run.initial_state_ok = start == SolveStatus::kConverged;
    run.status = start;
  }
  detail::ObstacleCoreWatch obstacles(problem.loads.contact);
  auto record = [&](double t) {
    model.ToRodState(q, v, &state);
    run.frame_t.push_back(t);
    run.frame_tip.push_back(state.tip_position_W());
    run.envelope.Add(state);
    if (run.report_anchor_force) {
      run.frame_anchor_force.push_back(state.rotation_WB.back() * state.wrench_B.back().tail<3>());
      run.frame_midspan.push_back(state.position_W[state.size() / 2]);
    }
    if (run.report_touchdown) run.frame_touchdown_s.push_back(detail::TouchdownS(problem, state));
    if (options.nodes_csv)
      run.frame_positions.insert(run.frame_positions.end(), state.position_W.begin(),
                                 state.position_W.end());
    if (options.frames) run.frame_states.push_back(state);
    if (options.progress) options.progress(t, d.duration);
  };
  RadauOutcome radau;
  if (!run.initial_state_ok) {
    run.failed_at_t = 0.0;
  } else {
    record(0.0);
    model.set_loads(problem.loads);
    model.set_gust(problem.gust);  // the drag follows each Radau stage's time
    if (problem.loads.contact.count > 0) obstacles.Observe(0.0, state.position_W);  // the start
    radau = IntegrateRadau(model, d, q, v, record, options.progress,
                           problem.loads.contact.count > 0 ? &obstacles : nullptr, &run);
  }
  run.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  model.ToRodState(q, v, &state);
  Result result;
  result.json = io::DynamicResultToJson(run, state);
  detail::MoveFrames(problem.rod, problem.robot.actuation, &run, &result);
  for (int i = 0; i < state.size(); ++i)
    result.node_velocity_W.push_back(state.rotation_WB[i] * state.twist_B[i].tail<3>());
  if (options.nodes_csv) result.nodes_csv = detail::TrajectoryCsv(run, state.s);
  result.log = DynamicsLog(run, radau, d, state) + start_log + RingingNote(problem, run) +
               obstacles.Warning(false);
  if (!run.initial_state_ok && start_log.empty()) result.log += ContactGridHint(problem);
  result.converged = run.status == SolveStatus::kConverged;
  return result;
}

}  // namespace cosserat::run
