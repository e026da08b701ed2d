#include "cosserat/run/run_dynamics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/io/result_writer.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/robots/rotary_table_drive.hpp"
#include "cosserat/run/grid_resolution.hpp"
#include "cosserat/run/initial_equilibrium.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/shooting_exponent.hpp"
#include "frame_output.hpp"
#include "node_table.hpp"
#include "obstacle_core_watch.hpp"

namespace cosserat::run {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The clamp held still at the problem's base pose, under `loads`.
StepInput ClampedInput(const io::Problem& problem, const StaticLoads& loads,
                       const Actuation& actuation) {
  StepInput input;
  input.actuation = actuation;
  input.base_pose = problem.base;
  input.base_twist_B = Vec6::Zero();
  input.loads = loads;
  // A column's tip slides along the base's axis, through the base (ColumnSolver's guide).
  input.tip_hold = GuidedTipHold(problem.boundary);
  if (input.tip_hold != TipHold::kFree) input.tip_pose = problem.base;
  return input;
}

/// The tip body's share of the energy (`dynamics.tip_mass`, `tip_inertia`), which the rod's
/// integrals leave out (J).
void AddTipBodyEnergy(const io::Problem& problem, const RodState& state, RodEnergy* energy) {
  const RodEnergy tip = TipBodyEnergy(problem.dynamics.tip_mass, problem.dynamics.tip_inertia,
                                      problem.loads.gravity_W, state);
  energy->kinetic += tip.kinetic;
  energy->potential += tip.potential;
}

/// The energy of the stepper's state under the problem's loads, the tip body's included (J).
RodEnergy RunEnergy(const io::Problem& problem, const Bdf2ShootingStepper& stepper) {
  RodEnergy e = stepper.Energy(problem.loads);
  AddTipBodyEnergy(problem, stepper.state(), &e);
  return e;
}

/// Whether the energy the result reports is conserved by the equations: no Kelvin–Voigt damping,
/// loads that neither depend on the motion (drag, contact) nor change (gusts, a spinning or driven
/// base, bit friction), no actuators, and no tip force or moment (their work is not in it: a
/// partial release "lost" 175 % of its kinetic energy).
bool ConservesEnergy(const io::Problem& problem) {
  const io::Problem::Dynamics& d = problem.dynamics;
  if (!problem.loads.tip_force.isZero(0.0) || !problem.loads.tip_moment.isZero(0.0) ||
      HasMotionLoads(problem.loads) || problem.gust.present() || d.base_spin != 0.0 ||
      d.rotary_table.present() || problem.loads.bit.present() || problem.has_robot ||
      !problem.rod.tendons.empty() || !problem.rod.chambers.empty())
    return false;
  const double L = problem.rod.length;
  for (int i = 0; i <= 20; ++i)
    if (!problem.rod.section->At(L * i / 20.0, problem.robot.actuation).damping.isZero(0.0))
      return false;
  return true;
}

/// Adds the stepper's current state as the frame at time t; node positions only when
/// `all_nodes`; with a motor-driven table or a given base_spin, the table's speed (rad/s) and the
/// string's torque on it.
void Record(const Bdf2ShootingStepper& stepper, double t, bool all_nodes, io::DynamicRun* run,
            double table_speed = 0.0) {
  const RodState& state = stepper.state();
  run->frame_t.push_back(t);
  run->frame_tip.push_back(state.tip_position_W());
  run->envelope.Add(state);
  if (run->report_tip_spin) run->frame_tip_spin.push_back(state.twist_B.back()(2));
  if (run->report_table) {
    run->frame_table_speed.push_back(table_speed);
    run->frame_table_torque.push_back(state.wrench_B.front()(2));  // m₃(0), N·m
  }
  if (all_nodes)
    run->frame_positions.insert(run->frame_positions.end(), state.position_W.begin(),
                                state.position_W.end());
  if (run->record_states) run->frame_states.push_back(state);
}

void AddCounts(const StepSummary& s, io::DynamicRun* run) {
  run->iterations += s.iterations;
  // The largest, a NaN kept (std::max would drop it).
  if (!(s.residual <= run->residual)) run->residual = s.residual;
  run->shots += s.shots;
}

/// The shear wave's exponent per grid segment at dt: h c0 sqrt(ρA / κGA), c0 = 1.5/dt (docs/
/// dynamics.md, "Grid and step"); the sections at s = 0.
double ShearWavePerSegment(const io::Problem& problem, double dt) {
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  return 1.5 / dt * problem.rod.length / (problem.nodes - 1) *
         std::sqrt(p.mass(3, 3) / p.stiffness.diagonal().segment<2>(3).minCoeff());
}

/// Past one per segment, the shear wave can grow an oscillation the grid does not carry, in
/// steps that all converge (a spun clamp on 41 nodes, 2.2 per segment: kinetic energy 6–10-fold
/// a step, 1e5 times the clamp's work within 7 steps). Kinetic energy growing over fourfold a
/// step, five steps in a row (a thousandfold), is taken for it: the rod's own motion grows that
/// fast only at a rate σ that dt does not resolve (e^{2σ dt} > 4, σ dt > 0.69), and loads that
/// rise from rest grow it so only if they rise as t³ or faster. Steps from kinetic energy under
/// 1e-12 EI/L (J, sections at s = 0) do not count: a rod at rest holds round-off there.
class GridOscillationWatch {
 public:
  GridOscillationWatch(const io::Problem& problem, double dt)
      : active_(ShearWavePerSegment(problem, dt) > 1.0) {
    const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
    floor_ = 1e-12 * p.min_bending_stiffness() / problem.rod.length;
  }
  /// After each converged step: true once the kinetic energy has grown as above.
  bool Grew(const io::Problem& problem, const Bdf2ShootingStepper& stepper) {
    if (!active_) return false;
    const double kinetic = RunEnergy(problem, stepper).kinetic;  // J
    growing_ = last_ > floor_ && kinetic > 4.0 * last_ ? growing_ + 1 : 0;
    last_ = kinetic;
    return growing_ >= 5;
  }

 private:
  bool active_;
  double floor_ = 0.0;  ///< J
  double last_ = 0.0;   ///< the last step's kinetic energy, J
  int growing_ = 0;     ///< steps in a row that grew it over fourfold
};

/// Steps from the initial state to the end (or the first failed step), timing each Step().
/// Times are reported as k dt (the stepper's own clock sums the steps, with rounding), except
/// after a failed step, which may have committed some halved sub-steps.
void StepToTheEnd(const io::Problem& problem, int steps, int stride, bool all_nodes,
                  const std::function<void(double, double)>& progress,
                  Bdf2ShootingStepper* stepper, detail::ObstacleCoreWatch* obstacles,
                  io::DynamicRun* run) {
  StepInput input = ClampedInput(problem, problem.loads, problem.robot.actuation);
  const double dt = problem.dynamics.dt, spin = problem.dynamics.base_spin;
  input.base_twist_B(2) = spin;
  std::optional<RotaryTableDrive> table;
  if (problem.dynamics.rotary_table.present())
    table.emplace(problem.dynamics.rotary_table, problem.base);
  const bool track_energy = ConservesEnergy(problem);
  GridOscillationWatch watch(problem, dt);
  const bool contact = problem.loads.contact.count > 0;
  if (contact) obstacles->Observe(0.0, stepper->state().position_W);  // the paths from the start
  const auto loop_start = Clock::now();
  for (int k = 1; k <= steps; ++k) {
    if (problem.gust.present())  // the flow of the step's end (BDF2 is implicit)
      input.loads.fluid = problem.gust.At(problem.loads.fluid, k * dt);
    if (spin != 0.0)  // the rotary table: the clamp turned about its own axis by spin t
      input.base_pose.R = problem.base.R * lie::SO3Exp(Vec3(0, 0, spin * k * dt));
    const auto t0 = Clock::now();
    const StepSummary s = table ? table->Step(stepper, &input, dt) : stepper->Step(input);
    run->step_time_s.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    AddCounts(s, run);
    if (!s.converged()) {
      run->status = s.status;
      run->failed_at_t = k * dt;
      // The halved sub-steps it committed (docs/dynamics.md) are the run's end.
      if (contact) obstacles->Observe(stepper->time(), stepper->state().position_W);
      break;
    }
    ++run->steps;
    if (s.halvings > 0) ++run->halved_steps;
    run->shooting_segments = std::max(run->shooting_segments, s.shooting_segments);
    if (contact) obstacles->Observe(k * dt, stepper->state().position_W);
    if (watch.Grew(problem, *stepper)) {  // its state is the final frame, under_resolved
      run->status = SolveStatus::kUnderResolved;
      run->failed_at_t = k * dt;
      break;
    }
    if (k % stride == 0) {
      Record(*stepper, k * dt, all_nodes, run,
             table ? table->speed() : problem.dynamics.base_spin);
      if (track_energy)  // for EnergyNote only
        run->peak_kinetic_energy =
            std::max(run->peak_kinetic_energy, RunEnergy(problem, *stepper).kinetic);
    }
    if (progress) progress(k * dt, problem.dynamics.duration);
  }
  run->stepping_wall_time_s = SecondsSince(loop_start);
  // A failed step may have committed halved sub-steps (at least dt / 2^max_halvings each).
  const double nominal = run->steps * dt;
  const bool past_nominal = std::abs(stepper->time() - nominal) > 1e-3 * dt;
  run->simulated_time_s = past_nominal ? stepper->time() : nominal;
  // The final state ends the trajectory even when it falls between two output intervals.
  if (run->frame_t.back() != run->simulated_time_s)
    Record(*stepper, run->simulated_time_s, all_nodes, run,
           table ? table->speed() : problem.dynamics.base_spin);
}

/// Whether `state` presses on a contact surface with friction, which may hold a rod the
/// frictionless statics count unstable (a finger on a sphere).
bool PressesOnAFrictionalSurface(const io::Problem& problem, const RodState& state) {
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const ContactSurface& surface = problem.loads.contact.surface[k];
    if (surface.friction > 0.0 && PressesOn(surface, state, [&problem](double s) {
          return 0.5 * problem.rod.section->At(s, problem.robot.actuation).outer_diameter;
        }))
      return true;
  }
  return false;
}

/// The whole simulation: initial equilibrium, then round(duration / dt) steps.
io::DynamicRun Simulate(const io::Problem& problem, const RunOptions& options,
                        Bdf2ShootingStepper* stepper, detail::ObstacleCoreWatch* obstacles) {
  const io::Problem::Dynamics& d = problem.dynamics;
  const auto [steps, stride] = detail::StepsOf(d);
  const bool all_nodes = options.nodes_csv;
  io::DynamicRun run;
  run.record_states = options.frames;
  run.report_tip_spin = problem.loads.bit.present() || d.base_spin != 0.0 ||
                        d.base_spin_given || d.rotary_table.present();
  run.step_time_s.reserve(steps);
  const std::size_t frames = steps / stride + 2;
  run.frame_t.reserve(frames);
  run.frame_tip.reserve(frames);
  if (run.report_tip_spin) run.frame_tip_spin.reserve(frames);
  run.report_table = d.rotary_table.present() || d.base_spin_given;
  if (all_nodes) run.frame_positions.reserve(frames * problem.nodes);

  const auto start = Clock::now();
  const StaticLoads& initial_loads = d.initial_loads.value_or(problem.loads);
  const StepInput initial =
      ClampedInput(problem, initial_loads, problem.robot.initial_actuation);
  StepSummary init =
      InitializeAtStaticEquilibrium(problem, initial, stepper, &run.initial_unstable_directions);
  AddCounts(init, &run);
  run.initial_state_ok = init.converged();
  if (PressesOnAFrictionalSurface(problem, stepper->state()))
    run.initial_unstable_directions = -1;  // the statics' count is frictionless: not judged
  run.status = init.status;
  if (!run.initial_state_ok) {
    run.failed_at_t = 0.0;
  } else {
    Record(*stepper, 0.0, all_nodes, &run, d.base_spin);  // a motor's table starts at rest
    // The start's energy is the balance's only under the actuation the run steps with: a change
    // at t = 0 (a chamber pressurised from the initial actuation) moves the rest strain, and
    // the work it does is in no term.
    if (problem.robot.initial_actuation == problem.robot.actuation)
      run.initial_total_energy = RunEnergy(problem, *stepper).total();
    StepToTheEnd(problem, steps, stride, all_nodes, options.progress, stepper, obstacles, &run);
    run.energy = RunEnergy(problem, *stepper);
  }
  run.wall_time_s = SecondsSince(start);
  return run;
}

std::string SummaryLine(const io::DynamicRun& run, const RodState& state) {
  std::ostringstream line;
  line << "cosserat: " << ToString(run.status);
  if (!run.initial_state_ok) {
    line << ", the initial equilibrium did not converge, " << std::setprecision(3)
         << run.wall_time_s * 1e3 << " ms";
    return line.str();
  }
  if (run.status != SolveStatus::kConverged)
    line << " in the step to t = " << std::setprecision(6) << run.failed_at_t << " s";
  line << ", " << run.steps << " steps, " << std::setprecision(6) << run.simulated_time_s
       << " s simulated in " << std::setprecision(3) << run.wall_time_s << " s ("
       << run.simulated_time_s / run.stepping_wall_time_s << "x real time)";
  const Vec3& tip = state.tip_position_W();
  line << ", tip at [" << std::setprecision(6) << tip.x() << ", " << tip.y() << ", " << tip.z()
       << "] m";
  return line.str();
}

/// BDF2's step of the undamped mode e^{iωt}: the root of (3 − 2iωdt) ζ² − 4ζ + 1 = 0 near
/// e^{iωdt}. |ζ| is the amplitude a step keeps, arg ζ / dt the frequency it runs at.
std::complex<double> Bdf2ModeStep(double wh) {
  const std::complex<double> a(3.0, -2.0 * wh);
  const std::complex<double> root = std::sqrt(std::complex<double>(16.0) - 4.0 * a);
  const std::complex<double> z1 = (4.0 + root) / (2.0 * a), z2 = (4.0 - root) / (2.0 * a);
  return std::abs(z1) > std::abs(z2) ? z1 : z2;
}

/// BDF2 damps a motion it resolves in few steps and slows it: per step a mode of angular
/// frequency ω keeps |ζ| ≈ 1 − (ω dt)⁴/4 of its amplitude (0.93 at ω dt = 1, 0.76 at 2;
/// docs/dynamics.md, "Numerical damping") and runs at arg ζ / dt, about (ω dt)²/3 slow (15 %
/// at ω dt = 0.88: a steel cantilever at dt = 25 ms, measured). When the rod's first bending
/// mode, as an unloaded cantilever's (β₁L = 1.8751) or free rod's (4.7300), runs 5 % slow or
/// more (ω dt > 0.43, under ~15 steps per period), a warning gives both and the dt that keeps
/// its frequency within 1 %.
std::string CoarseStepWarning(const io::Problem& problem, double dt) {
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double ei = p.min_bending_stiffness(), rho_a = p.mass(5, 5);
  const double beta_l = problem.boundary == io::Boundary::kFreeFree ? 4.7300 : 1.8751;
  const double omega = std::pow(beta_l / problem.rod.length, 2) * std::sqrt(ei / rho_a);
  const double wh = omega * dt;
  if (!std::isfinite(wh) || !(wh > 0.0)) return "";  // a massless rod (ρA = 0) has no period
  const std::complex<double> step = Bdf2ModeStep(wh);
  const double slow = 1.0 - std::arg(step) / wh;
  if (!(slow > 0.05)) return "";
  double lo = 0.0, hi = wh;  // the ω dt that runs 1 % slow
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (1.0 - std::arg(Bdf2ModeStep(mid)) / mid > 0.01 ? hi : lo) = mid;
  }
  std::ostringstream warning;
  warning << std::setprecision(3) << "cosserat: warning: dt = " << dt
          << " s resolves the first bending mode (about " << omega / (2 * M_PI)
          << " Hz as an unloaded rod) in " << 2 * M_PI / wh << " steps per period: BDF2 runs it "
          << 100 * slow << " % slow and keeps " << 100 * std::abs(step)
          << " % of its amplitude per step (docs/dynamics.md, \"Numerical damping\"); a dt below "
          << lo / omega << " s keeps its frequency within 1 %\n";
  return warning.str();
}

/// Automatic pieces bound each piece's gain; what they cannot fix is a grid too coarse for the
/// step: per segment, the bending exponent h λ and the shear wave's h c0 sqrt(ρA/GA) need to stay
/// below about 1 (docs/dynamics.md, "Grid and step"). Above it the steps can fail: a hint after
/// a failed run from 0.9 on. A shear wave above 1 per segment can also make converged steps
/// unstable: an undamped soft rod (shear 1.36, bending 2.12 per segment) gained energy sixfold a
/// step while every step converged, and failed at the twelfth; with shear at 0.91 or 0.68 (and
/// bending 1.4–1.5) its energy only fell, and drill strings run at bending 3. So a warning
/// whatever the outcome when the shear wave's exceeds 1.
std::string CoarseGridText(const io::Problem& problem, double dt, bool converged) {
  const double exponent = SingleShootingExponent(problem.rod, dt, problem.robot.actuation);
  const double shear_wave = ShearWavePerSegment(problem, dt) * (problem.nodes - 1);
  const double per_segment = std::max(exponent, shear_wave) / (problem.nodes - 1);
  const bool warn = shear_wave / (problem.nodes - 1) > 1.0;
  if (!std::isfinite(per_segment) || !(warn || (!converged && per_segment > 0.9))) return "";
  std::ostringstream text;
  text << "cosserat: " << (warn ? "warning" : "hint") << ": at dt = " << dt
       << " s the grid is coarse for the step: its exponent per segment is "
       << std::setprecision(3) << per_segment << " (bending " << exponent / (problem.nodes - 1)
       << ", shear " << shear_wave / (problem.nodes - 1) << "; above about 1 the steps can "
       << (warn ? "gain energy or fail" : "fail")
       << "; docs/dynamics.md, \"Grid and step\"); ";
  const double nodes = std::ceil(std::max(exponent, shear_wave) / 0.9) + 1;
  if (nodes <= io::kMaxRodNodes)
    text << "\"rod\": {\"nodes\": " << static_cast<long>(nodes) << "} or a larger dt\n";
  else  // past what a problem file takes
    text << "a larger dt: this one needs " << nodes << " nodes, past the limit of "
         << io::kMaxRodNodes << "\n";
  return text.str();
}

/// After a converged run of a rod whose equations conserve energy: BDF2 still dissipates what
/// dt resolves in few steps (docs/dynamics.md, "Numerical damping"), and only the first mode is
/// checked before the run. A soft rod released at dt = 5 ms loses 43 % of its largest kinetic
/// energy in 1 s and 56 % in 2 s (0.5 ms, on 81 nodes as that step needs: 7.5 % and 37 %: the
/// loss grows as the swing feeds faster motion). A note says how much went, from 1 % of the
/// largest kinetic energy on, and from 1e-8 of the elastic and largest kinetic energies: a rod
/// left at rest in its static equilibrium drifts by about 1e-9 of its elastic energy (the
/// steps' solve tolerance), which is no motion. (Not of the potential energy, which is measured
/// from the world's origin: moving the rod 1 km away would hide the note.)
std::string EnergyNote(const io::Problem& problem, const io::DynamicRun& run) {
  if (run.status != SolveStatus::kConverged || !ConservesEnergy(problem)) return "";
  const double loss = run.initial_total_energy - run.energy.total();
  const double size = std::abs(run.energy.elastic) + run.peak_kinetic_energy;  // J
  if (!(loss > 0.01 * run.peak_kinetic_energy) || !(run.peak_kinetic_energy > 0) ||
      !(loss > 1e-8 * size))
    return "";
  std::ostringstream note;
  note << std::setprecision(3) << "cosserat: note: the rod is undamped, yet its total energy fell by "
       << loss << " J over the run, ";
  const double share = loss / run.peak_kinetic_energy;  // above 1: damped before it swung
  if (share < 1)
    note << 100 * share << " % of";
  else
    note << share << " times";
  note << " its largest kinetic energy at the output frames: BDF2's numerical damping of "
          "motion that dt = "
       << problem.dynamics.dt
       << " s resolves in few steps (docs/dynamics.md, \"Numerical damping\"); a smaller dt "
          "keeps more, but slowly where the run excites motion far faster than its first mode "
          "(a soft rod swinging for 2 s lost 56 % at 5 ms and still 37 % at 0.5 ms, on the "
          "finer grid that step needs), and "
          "\"formulation\": \"quaternion-fd\" keeps it, its error control following every "
          "oscillation the run excites (slow for a stiff rod without damping: the steel "
          "release takes ~30 000 steps per simulated second)\n";
  return note.str();
}

/// After a start refused as non_finite: the grid check's words for the statics shot that ran
/// away, when it did (RunawayStartState).
std::string RunawayStartText(const io::Problem& problem) {
  const StepInput initial =
      ClampedInput(problem, problem.dynamics.initial_loads.value_or(problem.loads),
                   problem.robot.initial_actuation);
  const std::optional<RodState> state = RunawayStartState(problem, initial);
  return state ? CheckGrid(*state, problem.rod.length).log : "";
}

/// After a free-free rod's start failed under initial loads with gravity: at rest it has no
/// equilibrium in the air, and on a surface none that is unique (it slides along the surface and
/// turns about its normal at no cost). Starting unloaded lets it fall and settle in time.
std::string FreeStartHint(const io::Problem& problem) {
  const StaticLoads& initial = problem.dynamics.initial_loads.value_or(problem.loads);
  if (problem.boundary != io::Boundary::kFreeFree || initial.gravity_W.isZero(0.0)) return "";
  // The weight in the fluid with the distributed force, per metre at s = 0 (N/m): none where a
  // fluid or a force carries it (a neutrally buoyant rod), and then not this hint's case.
  const SectionProperties sp = problem.rod.section->At(0.0, problem.robot.initial_actuation);
  const double weight = sp.mass(5, 5) * initial.gravity_W.norm();
  const Vec3 net =
      TotalDistributedForce_W(initial, LoadSite{0.0, 1.0, sp.mass(5, 5), sp.outer_diameter});
  if (!(net.norm() > 1e-6 * weight)) return "";
  return std::string("cosserat: hint: a free-free rod under gravity has ") +
         (problem.loads.contact.count > 0
              ? "no unique equilibrium at rest on environment.contact (it slides along the "
                "surface and turns about its normal at no cost)"
              : "no equilibrium at rest") +
         "; \"dynamics\": {\"initial_loads\": {\"gravity\": [0, 0, 0]}} starts it unloaded, "
         "and it falls and settles in time\n";
}

/// After a failed step on a surface with friction: the regularised Coulomb law turns over
/// within slip_velocity, a switch as sharp as μN/v_ε (N·s/m per m) that Newton's iterates on a
/// step can keep jumping across. A 100 m pipe spun against a bore's wall (μ 0.3) failed its
/// second step at the default 1e-4 m/s on any number of pieces, and ran at 1e-3 m/s.
std::string FrictionSwitchHint(const io::Problem& problem) {
  for (int i = 0; i < problem.loads.contact.count; ++i) {
    const ContactSurface& surface = problem.loads.contact.surface[i];
    if (!(surface.friction > 0.0)) continue;
    std::ostringstream hint;
    hint << "cosserat: hint: environment.contact[" << i << "].friction turns over within "
         << "slip_velocity = " << surface.slip_velocity << " m/s, a switch the step's Newton "
         << "iterates may keep jumping across; a slip_velocity ten times larger softens it "
            "tenfold (the rod then creeps ten times faster under a sideways load below μN)\n";
    return hint.str();
  }
  return "";
}

/// A start the statics count unstable (a string pushed past its buckling load, straight): the
/// run keeps its symmetry, and only round-off may break it, late or never, where a real rod
/// buckles at once. A 100 m drill string with 20 kN on its bit, 4.4 times its hanging buckling
/// load, stayed exactly straight for 3 s.
std::string UnstableStartWarning(const io::DynamicRun& run) {
  if (!run.initial_state_ok || run.initial_unstable_directions <= 0) return "";
  std::ostringstream out;
  out << "cosserat: warning: the run starts from an unstable equilibrium ("
      << run.initial_unstable_directions << " unstable direction"
      << (run.initial_unstable_directions > 1 ? "s" : "")
      << "): nothing but round-off moves it off, so the rod may stay on it where a real one "
         "buckles; a small lateral load in dynamics.initial_loads starts it bent and lets it "
         "go (docs/dynamics.md)\n";
  return out.str();
}

}  // namespace

std::string DynamicsStartWarnings(const io::Problem& problem, double dt) {
  std::string out = CoarseStepWarning(problem, dt);
  if (problem.dynamics.shooting_segments == 0) out += CoarseGridText(problem, dt, true);
  return out;
}

Result RunDynamics(const io::Problem& problem, const RunOptions& run_options) {
  const Bdf2Options options = DynamicsOptions(problem);
  Bdf2ShootingStepper stepper(problem.rod, problem.nodes, options);
  detail::ObstacleCoreWatch obstacles(problem.loads.contact);
  io::DynamicRun run = Simulate(problem, run_options, &stepper, &obstacles);
  run.shot_steps = stepper.shot_steps();
  Result result;
  result.json = io::DynamicResultToJson(run, stepper.state());
  detail::MoveFrames(problem.rod, problem.robot.actuation, &run, &result);
  for (int i = 0; i < stepper.state().size(); ++i)
    result.node_velocity_W.push_back(stepper.state().rotation_WB[i] *
                                     stepper.state().twist_B[i].tail<3>());
  if (run_options.nodes_csv) result.nodes_csv = detail::TrajectoryCsv(run, stepper.state().s);
  std::ostringstream log;
  log << SummaryLine(run, stepper.state()) << '\n';
  if (!run.initial_state_ok && run.status == SolveStatus::kNonFinite)
    log << RunawayStartText(problem);
  if (!run.initial_state_ok && run.status != SolveStatus::kNonFinite)
    log << FreeStartHint(problem);
  const bool grid_oscillation =
      run.initial_state_ok && run.status == SolveStatus::kUnderResolved;  // GridOscillationWatch
  if (grid_oscillation)
    log << "cosserat: the kinetic energy grew over fourfold a step for five steps in a row, to "
        << std::setprecision(3) << run.energy.kinetic << " J at t = " << run.failed_at_t
        << " s: an oscillation of the grid at this dt, as the shear wave's exponent of "
        << ShearWavePerSegment(problem, options.dt)
        << " per segment (above 1) allows; the run stops there\n";
  if (run.initial_state_ok && run.status != SolveStatus::kConverged && !grid_oscillation &&
      options.shooting_segments == 1) {  // an explicit single shot
    // The usual cause of a failed step at small dt (docs/dynamics.md, "Where it stops").
    const double exponent =
        SingleShootingExponent(problem.rod, options.dt, problem.robot.actuation);
    if (exponent > 10.0)
      log << "cosserat: hint: at dt = " << options.dt << " s single shooting amplifies errors by"
          << " e^" << std::setprecision(3) << exponent
          << " along the rod (docs/dynamics.md, \"Where"
          << " it stops\"); \"dynamics\": {\"shooting_segments\": "
          << std::min(SuggestedShootingSegments(exponent), problem.nodes - 1)
          << "} shoots it in pieces\n";
  } else if (run.initial_state_ok && (options.shooting_segments == 0 || grid_oscillation)) {
    // The grid's fix (a watch-stopped run is always past 1 per segment: a warning with it).
    log << CoarseGridText(problem, options.dt, run.status == SolveStatus::kConverged);
  }
  if (run.initial_state_ok && run.status != SolveStatus::kConverged && !grid_oscillation)
    log << FrictionSwitchHint(problem);  // of failed steps
  log << obstacles.Warning(true) << CoarseStepWarning(problem, options.dt)
      << UnstableStartWarning(run) << EnergyNote(problem, run);
  result.log = log.str();
  result.converged = run.status == SolveStatus::kConverged;
  return result;
}

}  // namespace cosserat::run
