#include "cosserat/strong/bdf2_stepper.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/lie/nearest_rotation.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/frame_tangent.hpp"
#include "cosserat/strong/secant_filter.hpp"
#include "cosserat/strong/shooting_exponent.hpp"
#include "cosserat/strong/shot_newton.hpp"

namespace cosserat {

bool Bdf2Options::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(dt) && dt > 0)) return fail("dt must be a finite positive number");
  if (!(std::isfinite(tolerance) && tolerance > 0)) return fail("tolerance must be positive");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (max_halvings < 0) return fail("max_halvings must be >= 0");
  if (!(std::isfinite(tip_mass) && tip_mass >= 0)) return fail("tip_mass must be finite and >= 0");
  if (!(tip_inertia_B.allFinite() && (tip_inertia_B.array() >= 0).all()))
    return fail("tip_inertia must be finite and >= 0");
  if (shooting_segments < 0) return fail("shooting_segments must be 0 (automatic) or more");
  if (spatial_scheme != SpatialScheme::kRk4 && spatial_scheme != SpatialScheme::kHeun &&
      spatial_scheme != SpatialScheme::kRk4Pairs)
    return fail("spatial_scheme must be rk4, heun or rk4-pairs");
  return true;
}

namespace {

using Sample = Bdf2ShootingStepper::Sample;
using Coefficients = Bdf2ShootingStepper::Coefficients;

// Weights (c0, c1, c2) of the variable-step BDF2 derivative for a step h after a step h_prev:
// y' ≈ c0 y_n + c1 y_{n−1} + c2 y_{n−2}. Equal steps give eq. 23: 3/(2h), −2/h, 1/(2h).
// The first step of a run (h_prev = 0): backward Euler, 1/h, −1/h, 0, unless the options ask
// for BDF2 over the rest history (Bdf2Options::first_step). BDF2 over the rest history
// differences the jump in acceleration when the loads change at t = 0 (a release) and leaves a
// velocity error of a third of the jump times h, which an undamped rod keeps: the whole run is
// then first order. A backward Euler start is exact in the velocity for a constant acceleration,
// and its O(h²) position error keeps the run second order.
Coefficients Bdf2Weights(double h, double h_prev, Bdf2Options::FirstStep first) {
  if (!(h_prev > 0) && first == Bdf2Options::FirstStep::kBackwardEuler)
    return {1.0 / h, -1.0 / h, 0.0};
  const double w = h_prev > 0 ? h / h_prev : 1.0;
  return {(1 + 2 * w) / ((1 + w) * h), -(1 + w) / h, w * w / ((1 + w) * h)};
}

// a + t (b − a) for every input; the base rotation along the geodesic R_a Exp(t Log(R_aᵀ R_b)).
StepInput BlendInputs(const StepInput& a, const StepInput& b, double t) {
  StepInput out = b;
  out.base_pose.p = a.base_pose.p + t * (b.base_pose.p - a.base_pose.p);
  out.base_pose.R =
      a.base_pose.R * lie::SO3Exp(t * lie::SO3Log(a.base_pose.R.transpose() * b.base_pose.R));
  out.base_twist_B = a.base_twist_B + t * (b.base_twist_B - a.base_twist_B);
  out.base_wrench_B = a.base_wrench_B + t * (b.base_wrench_B - a.base_wrench_B);
  if (a.tip_hold == b.tip_hold && b.tip_hold != TipHold::kFree) {
    out.tip_pose.p = a.tip_pose.p + t * (b.tip_pose.p - a.tip_pose.p);
    out.tip_pose.R =
        a.tip_pose.R * lie::SO3Exp(t * lie::SO3Log(a.tip_pose.R.transpose() * b.tip_pose.R));
  }
  out.loads = StaticLoads::Blend(a.loads, b.loads, t);
  const Actuation &x = a.actuation, &y = b.actuation;
  auto lerp = [t](double u, double v) { return u + t * (v - u); };
  out.actuation.pressure = lerp(x.pressure, y.pressure);
  for (int i = 0; i < Actuation::kMaxTendons; ++i)
    out.actuation.tendon_tension[i] = lerp(x.tendon_tension[i], y.tendon_tension[i]);
  for (int i = 0; i < Actuation::kMaxChambers; ++i)
    out.actuation.chamber_pressure[i] = lerp(x.chamber_pressure[i], y.chamber_pressure[i]);
  for (int i = 0; i < Actuation::kMaxSegments; ++i)
    out.actuation.jamming_pressure[i] = lerp(x.jamming_pressure[i], y.jamming_pressure[i]);
  return out;
}

}  // namespace

Bdf2ShootingStepper::Bdf2ShootingStepper(const RodModel& model, int num_nodes,
                                         const Bdf2Options& options)
    : model_(model), options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("Bdf2Options: " + why);
  grid_ = ModelGrid(model_, num_nodes);
  const int n = static_cast<int>(grid_.size());

  if (!model_.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  SampleGrid();
  PlanSteps();
  run_.model_fingerprint = ModelFingerprint();
  const double EI = std::max(samples_[0].stiffness(0), samples_[0].stiffness(1));
  const double L = model_.length;
  scale_ << EI / L, EI / L, EI / L, EI / (L * L), EI / (L * L), EI / (L * L);

  const int stages = stage_slots_;
  for (auto* v : {&strain_now_, &run_.strain1, &run_.strain2, &twist_now_, &run_.twist1,
                  &run_.twist2, &strain_h_, &twist_h_})
    v->assign(stages, Vec6::Zero());
  position_now_.assign(stages, Vec3::Zero());
  run_.position1.assign(stages, Vec3::Zero());
  rotation_now_.assign(stages, Mat3::Identity());
  for (auto* v : {&velocity_W_now_, &run_.velocity_W1, &run_.velocity_W2, &velocity_W_h_})
    v->assign(stages, Vec3::Zero());
  run_.rotation1.assign(stages, Mat3::Identity());
  twist_scale_ << 1, 1, 1, L, L, L;
  run_.state.Resize(n);
  for (int i = 0; i < n; ++i) run_.state.s[i] = grid_[i];
  trial_ = run_.state;

  automatic_pieces_ = options_.shooting_segments == 0;
  int pieces = options_.shooting_segments;
  if (automatic_pieces_) {
    pieces = PiecesFor(SingleShootingExponent(model_, options_.dt));
  }
  if (pieces > n - 1)  // PlanSteps() leaves as many steps as pieces
    throw std::invalid_argument("Bdf2Options: shooting_segments (" + std::to_string(pieces) +
                                ") exceeds the number of grid segments (" + std::to_string(n - 1) +
                                ")");
  initial_pieces_ = pieces;
  SetShootingPieces(pieces);
}

int Bdf2ShootingStepper::PiecesFor(double exponent) const {
  return AutomaticShootingPieces(exponent, MaxAutomaticPieces());
}

int Bdf2ShootingStepper::ChosenPieces() const {
  return PiecesFor(SingleShootingExponent(model_, options_.dt, actuation_, run_.state));
}

// kFirstDropWait: a failure's pieces are kept through 10 steps of the transient that asked for
// them, then halved, so a spike of one tick in the input costs about 40 dear steps after it, not
// 300. kLongestDropWait: a state that keeps needing the pieces is tried at most once in 160
// steps (a failed attempt costs about one step's solve).
void Bdf2ShootingStepper::DropUnneededPieces() {
  // Whole steps count at one piece too: a drop to one piece that holds a whole wait must bring
  // the wait back, or a spike hundreds of steps later would double it as if the drop had failed.
  if (!automatic_pieces_ || ++run_.whole_steps < run_.drop_wait) return;
  run_.whole_steps = 0;
  if (run_.dropped_pieces) run_.drop_wait = kFirstDropWait;  // the last drop held a whole wait
  run_.dropped_pieces = false;
  if (ShootingPieces() == 1) return;
  const int fewer = std::max(ChosenPieces(), ShootingPieces() / 2);
  run_.dropped_pieces = fewer < ShootingPieces();
  if (fewer < ShootingPieces()) SetShootingPieces(fewer);
}

void Bdf2ShootingStepper::NoteAddedPieces() {
  if (run_.dropped_pieces) run_.drop_wait = std::min(2 * run_.drop_wait, kLongestDropWait);
  run_.dropped_pieces = false;
}

int Bdf2ShootingStepper::MaxAutomaticPieces() const {
  return std::max(1, std::min(kMostAutomaticPieces, shot_steps()));
}

double Bdf2ShootingStepper::StepRate(const Sample& smp) const {
  // Along s the BDF2 step's rod bends like e^{λs}, λ = (c0² ρA / EI)^¼, c0 = 1.5/dt
  // (shooting_exponent.hpp), and each wave of the section (rotary, torsional, shear, axial:
  // inertia M_k against stiffness K_k) goes like e^{c0 s sqrt(M_k / K_k)}.
  const double c0 = 1.5 / options_.dt;
  double rate = std::pow(c0 * c0 * smp.mass(5) / smp.stiffness.head<2>().minCoeff(), 0.25);
  for (int k = 0; k < 6; ++k) rate = std::max(rate, c0 * std::sqrt(smp.mass(k) / smp.stiffness(k)));
  return rate;
}

void Bdf2ShootingStepper::PlanSteps(int keep) {
  const int segments = static_cast<int>(grid_.size()) - 1;
  pair_start_.resize(std::max(segments, 0));
  std::fill(pair_start_.begin() + keep, pair_start_.end(), 0);
  if (options_.spatial_scheme == SpatialScheme::kRk4Pairs) {
    const std::vector<double> breaks = model_.Breakpoints();
    for (int i = keep; i + 1 < segments; ++i) {
      const double h0 = grid_[i + 1] - grid_[i], h1 = grid_[i + 2] - grid_[i + 1];
      const double mid = grid_[i + 1];
      const bool on_break = std::any_of(breaks.begin(), breaks.end(), [&](double b) {
        return std::abs(b - mid) <= 1e-9 * model_.length;
      });
      if (std::abs(h0 - h1) > 1e-9 * h0 || on_break) continue;
      double rate = 0.0;
      for (int k : {3 * i, 3 * i + 3, 3 * i + 5}) rate = std::max(rate, StepRate(samples_[k]));
      if ((h0 + h1) * rate > kMaxPairExponent) continue;
      pair_start_[i] = 1;
      ++i;  // the pair's second segment
    }
    // Junctions sit where steps start: more pieces asked for than there are steps leave every
    // segment alone (plain RK4), as before the pairs.
    if (keep == 0 && options_.shooting_segments > shot_steps())
      std::fill(pair_start_.begin(), pair_start_.end(), 0);
  }
  step_slot_.assign(std::max(segments, 0), -1);
  stage_slots_ = 0;
  for (int i = 0; i < segments; ++i) {
    if (!StepStartsAt(i)) continue;
    step_slot_[i] = stage_slots_;
    stage_slots_ += StepTable(i).stages;
  }
}

void Bdf2ShootingStepper::SetShootingPieces(int pieces) {
  run_.whole_steps = 0;
  const int junctions = pieces - 1;
  const int unknowns = 6 + 18 * junctions;
  junction_nodes_.resize(junctions);
  PlaceJunctions();
  junction_z_.setZero(18 * junctions);
  junction_mismatch_.setZero(18 * junctions);
  run_.junction_unknowns.setZero(18 * junctions);
  if (junctions == 0) return;
  for (auto* v : {&ms_x_, &ms_x_new_, &ms_r_, &ms_r_new_, &ms_dx_}) v->setZero(unknowns);
  ms_piece_base_.setZero(18);
  ms_piece_new_.setZero(18);
  // Junction k's rows reach back to the start of its piece (12 columns before the row block:
  // 29 sub-diagonals) and forward to its own unknowns (23 super-diagonals).
  run_.junction_factors.Resize(unknowns, 29, 23);
  run_.junction_factors_c0 = -1.0;  // no Jacobian for these unknowns yet
}

void Bdf2ShootingStepper::PlaceJunctions() {
  // Pieces of about equal step count; a junction sits where a step of the shot starts (every
  // node but a pair's middle, kRk4Pairs): junction k at the start of step round(k steps / pieces).
  const int pieces = static_cast<int>(junction_nodes_.size()) + 1;
  const int steps = shot_steps();
  int node = 0, step = 0;
  for (int k = 1; k < pieces; ++k) {
    const int target = static_cast<int>(std::lround(double(k) * steps / pieces));
    while (step < target) step += StepStartsAt(++node);
    junction_nodes_[k - 1] = node;
  }
  run_.junction_factors_c0 = -1.0;  // the junctions moved: the factors are stale
}

void Bdf2ShootingStepper::SampleGrid() {
  sample_points_ = SegmentSamplePoints(grid_);
  samples_.resize(sample_points_.size());
  if (!model_.tendons.empty()) {
    tendons_.resize(sample_points_.size());
    for (size_t q = 0; q < sample_points_.size(); ++q)
      tendons_[q] = SampleTendons(model_.tendons, sample_points_[q], model_.length);
  }
  SampleSections();
}

void Bdf2ShootingStepper::SampleSections() {
  for (size_t q = 0; q < sample_points_.size(); ++q) {
    const double s = sample_points_[q];
    const SectionLaw law = SectionLaw::At(model_, s, actuation_);
    Sample& smp = samples_[q];
    smp.stiffness = law.stiffness;
    smp.damping = law.damping;
    smp.compliance = smp.stiffness.cwiseInverse();
    smp.rest_strain = law.rest_strain;
    smp.mass = law.mass;
    smp.s = s;
    smp.outer_diameter = law.outer_diameter;
    smp.implicit_compliance = smp.compliance;
    smp.implicit_damping.setZero();
    smp.implicit_offset = smp.rest_strain;
  }
  current_c0_ = -1.0;  // the implicit compliance must be recomputed
}

void Bdf2ShootingStepper::ApplyActuation(const Actuation& a) {
  // Tensions enter the strain law directly; the section (and the chambers' rest-strain shift)
  // depends on the other fields, so only their change costs a re-sampling (no allocation).
  const bool section_changed = a.stiffness_scale != actuation_.stiffness_scale ||
                               a.pressure != actuation_.pressure ||
                               a.chamber_pressure != actuation_.chamber_pressure ||
                               a.jamming_pressure != actuation_.jamming_pressure;
  actuation_ = a;
  if (!section_changed) return;
  SampleSections();
  // A softer section raises the shot's exponent: with automatic pieces, shoot in as many as it
  // asks for now, rather than after a failed step (fewer only after whole steps:
  // DropUnneededPieces).
  if (automatic_pieces_) {
    const int wanted = PiecesFor(SingleShootingExponent(model_, options_.dt, actuation_));
    if (wanted > ShootingPieces()) SetShootingPieces(wanted);
  }
}

void Bdf2ShootingStepper::SetImplicitCompliance(double c0) {
  if (c0 == current_c0_) return;
  for (Sample& smp : samples_) {
    smp.implicit_compliance = (smp.stiffness + c0 * smp.damping).cwiseInverse();
    smp.implicit_damping = smp.implicit_compliance.cwiseProduct(smp.damping);
    smp.implicit_offset = smp.rest_strain - c0 * smp.implicit_damping.cwiseProduct(smp.rest_strain);
    smp.damped = (smp.damping.array() != 0.0).any();
  }
  current_c0_ = c0;
}

bool Bdf2ShootingStepper::SolveStep(const StepInput& input, const Coefficients& c, double h,
                                    bool statics, StepSummary* summary) {
  if (!statics && !junction_nodes_.empty()) return SolveStepMultiple(input, c, h, false, summary);
  Vec6 x = statics ? run_.unknowns.latest() : run_.unknowns.Predict(h);
  Vec6 r;
  if (SolveStepBySecantNewton(input, c, statics, &x, &r, summary)) return true;
  // Levenberg–Marquardt from the best point Newton reached (it only moves on a decrease of the
  // residual), or the last step's unknowns if that is not finite.
  return SolveStepByLevenbergMarquardt(input, c, statics,
                                       r.allFinite() ? x : run_.unknowns.latest(), summary);
}

bool Bdf2ShootingStepper::SolveStepBySecantNewton(const StepInput& input, const Coefficients& c,
                                                  bool statics, Vec6* x_io, Vec6* r_out,
                                                  StepSummary* summary) {
  // Newton with the last steps' Jacobian, tracked by the secant filter below, from the
  // predicted unknowns. A Jacobian from another c0 (statics, another step size) is replaced by
  // the exact one first.
  Vec6& x = *x_io;
  Vec6& r = *r_out;
  bool fresh = false;  // the filter's J is the exact Jacobian at x, not yet updated
  // The Jacobian: the secant filter's estimate (secant_filter.hpp), carried from the last steps;
  // this step's copy replaces it only if the step converges.
  SecantFilter filter = run_.jacobian_filter;
  if (run_.jacobian_c0 != c.c0) {
    r = RestartWithExactJacobian(input, c, statics, x, &filter, summary);
    run_.jacobian_c0 = c.c0;
    fresh = true;
  } else {
    r = Residual(input, c, statics, x);
    ++summary->shots;
    if (!statics) filter.Advance();
  }
  const Mat6& J = filter.jacobian();
  Eigen::PartialPivLU<Mat6> lu(J);
  bool ok = false;
  bool retried = false;  // a rejected Broyden step has been retried with its secant
  for (int it = 0; it < options_.max_iterations; ++it) {
    const double norm = r.norm();
    if (!std::isfinite(norm)) break;
    if (norm < Tolerance(x, input)) {
      ok = true;
      break;
    }
    Vec6 dx = -lu.solve(r);
    Vec6 r_new = Residual(input, c, statics, x + dx);
    ++summary->shots;
    ++summary->iterations;
    bool accepted = r_new.allFinite() && r_new.norm() < 0.5 * norm;
    if (!accepted && !fresh && r_new.allFinite() && !retried) {
      // A Broyden step that failed to halve the residual still measured the shot along dx: put
      // that secant into J and try again from x once, before paying for the exact Jacobian
      // (about ten shots; on the peer problem this retry avoids it in all but one of 12 500 steps,
      // which is what keeps the slowest steps near the median).
      retried = true;
      filter.Update(dx, r_new - r);
      lu.compute(J);
      continue;
    }
    if (!accepted && fresh) {
      // An exact Newton step overshot (the shot is strongly nonlinear when its exponent λL is
      // large): backtrack along it.
      accepted = BacktrackExactStep(input, c, statics, x, norm, &dx, &r_new, summary);
      if (!accepted) break;  // leave it to Levenberg–Marquardt
    }
    if (accepted) {
      filter.Update(dx, r_new - r);
      fresh = false;
      x += dx;
      r = r_new;
    } else {
      // The filtered Jacobian has drifted: replace it by the exact one at x and retry. The
      // exact J restarts the filter here too: kept, the rate that had made J fail would be added
      // again at the next step (an out-of-plane kick after a planar swing then needed an exact J
      // in nearly every one of the next ~80 steps).
      r = RestartWithExactJacobian(input, c, statics, x, &filter, summary);
      fresh = true;
    }
    lu.compute(J);
  }
  if (ok) {
    summary->residual = r.norm();
    run_.jacobian_filter = filter;
    solved_unknowns_ = x;
    // The root estimate one more (shot-free) Newton step gives: x's residual, up to the
    // tolerance, would otherwise enter the extrapolation of the next steps as noise.
    predictor_term_ = x - lu.solve(r);
    return true;
  }
  return false;
}

Vec6 Bdf2ShootingStepper::RestartWithExactJacobian(const StepInput& input, const Coefficients& c,
                                                   bool statics, const Vec6& x,
                                                   SecantFilter* filter, StepSummary* summary) {
  Mat6 exact;
  const Vec6 r = Residual(input, c, statics, x, &exact);
  filter->Restart(exact);
  ++summary->jacobians;
  ++summary->shots;
  return r;
}

bool Bdf2ShootingStepper::BacktrackExactStep(const StepInput& input, const Coefficients& c,
                                             bool statics, const Vec6& x, double norm, Vec6* dx,
                                             Vec6* r_new, StepSummary* summary) {
  // Armijo's sufficient decrease, ‖r(x + α dx)‖ < (1 − α/2) ‖r(x)‖, for α = 1/2 … 1/16.
  for (double alpha = 0.5; alpha >= 1.0 / 16; alpha *= 0.5) {
    *dx *= 0.5;
    *r_new = Residual(input, c, statics, x + *dx);
    ++summary->shots;
    if (r_new->allFinite() && r_new->norm() < (1 - 0.5 * alpha) * norm) return true;
  }
  return false;
}

bool Bdf2ShootingStepper::SolveStepByLevenbergMarquardt(const StepInput& input,
                                                        const Coefficients& c, bool statics,
                                                        const Vec6& x_start, StepSummary* summary) {
  // Levenberg–Marquardt with the exact Jacobian.
  Mat6 J_lm = run_.jacobian_filter.jacobian();
  auto shot = [&](const Vec6& x_try, Mat6* J_try) {
    return Residual(input, c, statics, x_try, J_try);
  };
  Vec6 x_lm = x_start;
  const ShotSolveCounts counts =
      LevenbergMarquardtShot(shot, Tolerance(x_start, input), options_.max_iterations, &x_lm,
                             &J_lm);
  summary->shots += counts.shots;
  summary->jacobians += counts.jacobians;
  summary->iterations += counts.iterations;
  const Vec6 r_final = Residual(input, c, statics, x_lm);  // leaves the trial state at x_lm
  ++summary->shots;
  summary->residual = r_final.norm();
  if (!(r_final.allFinite() && summary->residual < Tolerance(x_lm, input))) {
    summary->status = r_final.allFinite() ? SolveStatus::kMaxIterations : SolveStatus::kNonFinite;
    return false;
  }
  run_.jacobian_filter.Restart(J_lm);
  run_.jacobian_c0 = c.c0;
  solved_unknowns_ = x_lm;
  predictor_term_ = x_lm;
  return true;
}

void Bdf2ShootingStepper::Commit(double h) {
  // Degrees scored in residual units with the Jacobian the next step starts from (single
  // shooting; multiple shooting keeps its own).
  run_.unknowns.Push(predictor_term_, h,
                     junction_nodes_.empty() ? &run_.jacobian_filter.jacobian() : nullptr);
  std::swap(run_.strain2, run_.strain1);
  std::swap(run_.strain1, strain_now_);
  std::swap(run_.twist2, run_.twist1);
  std::swap(run_.twist1, twist_now_);
  std::swap(run_.position1, position_now_);
  std::swap(run_.rotation1, rotation_now_);
  std::swap(run_.velocity_W2, run_.velocity_W1);
  std::swap(run_.velocity_W1, velocity_W_now_);
  run_.tip_strain2 = run_.tip_strain1;
  run_.tip_strain1 = tip_strain_now_;
  run_.tip_twist2 = run_.tip_twist1;
  run_.tip_twist1 = tip_twist_now_;
  std::swap(run_.state, trial_);
  history_ready_ = false;
  stage_strains_current_ = false;
  run_.base2 = run_.base1;
  run_.base1 = base_now_;
  run_.time += h;
  run_.last_dt = h;
  ++run_.steps_taken;
}

void Bdf2ShootingStepper::RequireActuation(const Actuation& a) const {
  a.Require(static_cast<int>(model_.tendons.size()), static_cast<int>(model_.chambers.size()));
}

bool Bdf2ShootingStepper::InputIsFinite(const StepInput& input) const {
  // Only what these ends use: a free tip's pose and a clamped base's wrench are not read.
  const bool tip_held = input.tip_hold != TipHold::kFree;
  const bool base_free = options_.ends == EndConditions::kFreeFree;
  return input.loads.IsValid(nullptr) && input.base_twist_B.allFinite() &&
         (!base_free || input.base_wrench_B.allFinite()) && input.base_pose.R.allFinite() &&
         input.base_pose.p.allFinite() &&
         (!tip_held || (input.tip_pose.R.allFinite() && input.tip_pose.p.allFinite())) &&
         input.actuation.AllFinite();
}

void Bdf2ShootingStepper::RequirePoses(const StepInput& input) const {
  lie::RequireRotation(input.base_pose.R, "Bdf2ShootingStepper: StepInput.base_pose.R");
  if (input.tip_hold != TipHold::kFree)
    lie::RequireRotation(input.tip_pose.R, "Bdf2ShootingStepper: StepInput.tip_pose.R");
}

Bdf2ShootingStepper::Coefficients Bdf2ShootingStepper::Weights(double h, double h_prev,
                                                               Bdf2Options::FirstStep first) {
  return Bdf2Weights(h, h_prev, first);
}

bool Bdf2ShootingStepper::Attempt(const StepInput& input, double h, StepSummary* summary) {
  ApplyActuation(input.actuation);
  const Coefficients c = Bdf2Weights(h, run_.last_dt, options_.first_step);
  SetImplicitCompliance(c.c0);
  xi_back_ = lie::SE3Log(lie::Compose(lie::Inverse(run_.base1), run_.base2));
  if (SolveStep(input, c, h, false, summary)) {
    if (trial_.RanAway()) {  // residuals met by a shot that diverged (RodState::RanAway)
      summary->status = SolveStatus::kNonFinite;
      return false;
    }
    Commit(h);
    run_.last_input = input;
    return true;
  }
  return false;
}

bool Bdf2ShootingStepper::AttemptInterval(const StepInput& from, const StepInput& to, double h,
                                          int depth, StepSummary* summary) {
  if (Attempt(to, h, summary)) return true;
  // A segment that ran away needs a finer grid (frames that left the rotations may not).
  auto ran_away = [&] {
    return summary->status == SolveStatus::kNonFinite && trial_.SegmentsRanAway();
  };
  if (ran_away()) return false;
  // Before halving: more pieces, when the stepper chooses them (a failed attempt commits
  // nothing; the new junctions start from the last accepted state).
  while (automatic_pieces_ && ShootingPieces() < MaxAutomaticPieces()) {
    NoteAddedPieces();
    SetShootingPieces(std::min(MaxAutomaticPieces(), 2 * ShootingPieces()));
    if (Attempt(to, h, summary)) return true;
    if (ran_away()) return false;
  }
  if (depth >= options_.max_halvings) return false;
  summary->halvings = std::max(summary->halvings, depth + 1);
  // Sub-steps see the input interpolated between the start and the end of the interval.
  const StepInput mid = BlendInputs(from, to, 0.5);
  return AttemptInterval(from, mid, 0.5 * h, depth + 1, summary) &&
         AttemptInterval(mid, to, 0.5 * h, depth + 1, summary);
}

StepSummary Bdf2ShootingStepper::Step(const StepInput& input) {
  const auto t0 = std::chrono::steady_clock::now();
  StepSummary summary;
  if (!initialized_) {
    summary.status = SolveStatus::kNotRun;
    return summary;
  }
  // Try the whole step; on failure, two half steps, recursively up to max_halvings deep. Sub-steps
  // commit as they go, so a failure part-way leaves the last converged sub-step. (With shooting,
  // smaller steps raise the shot's exponent λL ∝ dt^(-1/2), so halving helps less than usual.)
  // NaN or Inf in the input, or a clock the step would take past the largest double (a dt of
  // 1e308): the state stays put.
  if (!InputIsFinite(input) || !std::isfinite(run_.time + options_.dt)) {
    summary.status = SolveStatus::kNonFinite;
    return summary;
  }
  RequireActuation(input.actuation);  // RequireValidInput, finiteness known
  RequirePoses(input);
  const StepInput start = run_.last_input;
  const int pieces = ShootingPieces();
  const bool ok = AttemptInterval(start, input, options_.dt, 0, &summary);
  if (ok) summary.status = SolveStatus::kConverged;
  if (ok && summary.halvings == 0 && ShootingPieces() == pieces)
    DropUnneededPieces();
  else
    run_.whole_steps = 0;
  summary.shooting_segments = ShootingPieces();
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

RodQuadrature Bdf2ShootingStepper::QuadraturePoints() const {
  // The scheme's quadrature on each step (RK4: h/6, h/3, h/3, h/6; Heun: h/2, h/2; a pair of
  // segments: RK4's weights times the pair's length).
  RodQuadrature points;
  points.reserve(stage_slots_);
  for (int i = 0; i + 1 < static_cast<int>(grid_.size()); ++i) {
    if (!StepStartsAt(i)) continue;
    const internal::SchemeTable& T = StepTable(i);
    const double h = grid_[i + StepSpan(i)] - grid_[i];
    for (int j = 0; j < T.stages; ++j) {
      const int q = step_slot_[i] + j;
      points.push_back({&samples_[3 * i + T.sample[j]], run_.position1[q], run_.rotation1[q],
                        run_.twist1[q], run_.strain1[q], h * T.weight[j]});
    }
  }
  return points;
}

}  // namespace cosserat
