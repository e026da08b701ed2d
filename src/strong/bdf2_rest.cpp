// Bdf2ShootingStepper at rest: the static equilibrium a run starts from, solved on the stepper's
// own equations, and the history that says the rod has been there.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/shooting_exponent.hpp"

namespace cosserat {

StepSummary Bdf2ShootingStepper::InitializeAtRest(const StepInput& input,
                                                  const Vec6* base_wrench_B) {
  return InitializeAtRestFrom(input, base_wrench_B, nullptr);
}

StepSummary Bdf2ShootingStepper::InitializeAtRest(const StepInput& input,
                                                  const RodState& equilibrium) {
  if (options_.ends != EndConditions::kCantilever)
    throw std::invalid_argument(
        "Bdf2ShootingStepper: an equilibrium to start from needs cantilever ends");
  bool on_grid = equilibrium.size() == static_cast<int>(grid_.size()) &&
                 static_cast<int>(equilibrium.position_W.size()) == equilibrium.size() &&
                 static_cast<int>(equilibrium.rotation_WB.size()) == equilibrium.size() &&
                 static_cast<int>(equilibrium.wrench_B.size()) == equilibrium.size();
  for (int i = 0; on_grid && i < equilibrium.size(); ++i)
    on_grid = std::abs(equilibrium.s[i] - grid_[i]) <= 1e-12 * model_.length;
  if (!on_grid)
    throw std::invalid_argument("Bdf2ShootingStepper: the equilibrium to start from has " +
                                std::to_string(equilibrium.size()) +
                                " nodes that are not this stepper's grid of " +
                                std::to_string(grid_.size()));
  return InitializeAtRestFrom(input, &equilibrium.wrench_B.front(), &equilibrium);
}

StepSummary Bdf2ShootingStepper::InitializeAtRestFrom(const StepInput& input,
                                                      const Vec6* base_wrench_B,
                                                      const RodState* equilibrium) {
  const auto t0 = std::chrono::steady_clock::now();
  StepSummary summary;
  if (options_.ends == EndConditions::kFreeFree && input.tip_hold != TipHold::kFree)
    throw std::invalid_argument("Bdf2ShootingStepper: a held tip needs cantilever ends");
  if (!InputIsFinite(input)) {  // NaN or Inf: no rest state, and the last run stays as it was
    summary.status = SolveStatus::kNonFinite;
    return summary;
  }
  RequireActuation(input.actuation);  // RequireValidInput, finiteness known
  RequirePoses(input);
  initialized_ = false;  // until this succeeds, Step() refuses to run and Save() has no run
  run_.initialized = false;
  // A new run starts from the constructor's plan, with its junctions' states and guesses as a
  // new stepper's: pieces a failed step of an earlier run added, or the junction states it left,
  // would make the same inputs give another run (ApplyActuation adds what this one asks for).
  SetShootingPieces(automatic_pieces_ ? initial_pieces_ : ShootingPieces());
  run_.base1 = run_.base2 = input.base_pose;
  run_.steps_taken = 0;
  run_.whole_steps = 0;
  run_.drop_wait = kFirstDropWait;
  run_.dropped_pieces = false;
  run_.jacobian_c0 = -1.0;  // the first solve computes the exact Jacobian
  ApplyActuation(input.actuation);
  bool ok = SolveRestEquilibrium(input, base_wrench_B, equilibrium, &summary);
  if (ok && trial_.RanAway()) {  // residuals met by a shot that diverged (RodState::RanAway)
    ok = false;
    summary.status = SolveStatus::kNonFinite;
  }
  if (!ok) {
    summary.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return summary;
  }
  StartHistoryAtRest(input);
  // The tension now known may ask for more pieces than dt alone (a rod held in tension).
  if (options_.ends == EndConditions::kCantilever) AddPiecesForTension();
  summary.shooting_segments = ShootingPieces();
  summary.status = SolveStatus::kConverged;
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

bool Bdf2ShootingStepper::SolveRestEquilibrium(const StepInput& input, const Vec6* base_wrench_B,
                                               const RodState* equilibrium,
                                               StepSummary* summary_out) {
  StepSummary& summary = *summary_out;
  const Coefficients c{};
  bool ok = false;
  if (options_.ends == EndConditions::kFreeFree) {
    // Nothing to solve: W(0) is given, V = 0. The rod is at rest only if the loads balance.
    run_.unknowns.Reset(Vec6::Zero());
    const Vec6 r = Residual(input, c, true, Vec6::Zero());
    ++summary.shots;
    summary.residual = r.norm();
    ok = summary.residual < options_.tolerance;
    if (!ok) summary.status = SolveStatus::kMaxIterations;  // not an equilibrium
  } else {
    // A rigid-body guess is good enough for moderate preloads; large ones are the statics
    // solver's job (continuation). The tip frame of the guess is the clamp's: a follower force
    // turns with it.
    const SplitWrench tip = TotalTipWrench(input.loads, options_.tip_mass);
    const Vec3 total = model_.length * TotalDistributedForce_W(input.loads, samples_[1].Site()) +
                       tip.dead_W.tail<3>() + input.base_pose.R * tip.follower_B.tail<3>();
    Vec6 W;
    W << Vec3::Zero(), input.base_pose.R.transpose() * total;
    if (base_wrench_B) W = *base_wrench_B;
    if (!equilibrium) {
      run_.unknowns.Reset(W.cwiseQuotient(scale_));
      ok = SolveStep(input, c, 0.0, true, &summary);
    } else {
      // In as many pieces as the equilibrium's tension asks for; where they do not converge
      // (a held string just below that count: Newton on a single shot of gain ~e^9 stalled at
      // 3e-7), in twice as many, as a failed step does before it halves dt.
      StartFromEquilibrium(*equilibrium, W);
      AddPiecesForTension();
      while (true) {
        ok = junction_nodes_.empty() ? SolveStep(input, c, 0.0, true, &summary)
                                     : SolveStepMultiple(input, c, 0.0, true, &summary);
        if (ok || !automatic_pieces_ || ShootingPieces() >= MaxAutomaticPieces()) break;
        SetShootingPieces(std::min(MaxAutomaticPieces(), 2 * ShootingPieces()));
        StartFromEquilibrium(*equilibrium, W);
      }
    }
    if (ok) run_.unknowns.Reset(solved_unknowns_);
  }
  return ok;
}

void Bdf2ShootingStepper::StartFromEquilibrium(const RodState& equilibrium, const Vec6& W) {
  // The unknowns and the junctions start from the given equilibrium, twists zero.
  run_.unknowns.Reset(W.cwiseQuotient(scale_));
  for (int i = 0; i < equilibrium.size(); ++i) {
    run_.state.position_W[i] = equilibrium.position_W[i];
    run_.state.rotation_WB[i] = equilibrium.rotation_WB[i];
    run_.state.wrench_B[i] = equilibrium.wrench_B[i];
    run_.state.twist_B[i].setZero();
  }
}

void Bdf2ShootingStepper::StartHistoryAtRest(const StepInput& input) {
  // At rest: both history levels equal the equilibrium, twists zero.
  std::copy(strain_now_.begin(), strain_now_.end(), run_.strain1.begin());
  std::copy(strain_now_.begin(), strain_now_.end(), run_.strain2.begin());
  std::copy(position_now_.begin(), position_now_.end(), run_.position1.begin());
  std::copy(rotation_now_.begin(), rotation_now_.end(), run_.rotation1.begin());
  std::swap(run_.state, trial_);
  for (auto* v : {&run_.twist1, &run_.twist2}) std::fill(v->begin(), v->end(), Vec6::Zero());
  for (auto* v : {&run_.velocity_W1, &run_.velocity_W2})
    std::fill(v->begin(), v->end(), Vec3::Zero());
  run_.tip_strain1 = run_.tip_strain2 = tip_strain_now_;
  run_.tip_twist1 = run_.tip_twist2 = Vec6::Zero();
  run_.last_input = input;
  run_.last_input.base_twist_B.setZero();
  history_ready_ = false;
  run_.time = 0.0;
  run_.last_dt = 0.0;
  run_.steps_taken = 0;
  run_.whole_steps = 0;
  run_.initialized = true;
  initialized_ = true;
}

void Bdf2ShootingStepper::AddPiecesForTension() {
  if (!automatic_pieces_) return;
  const int wanted = ChosenPieces();
  if (wanted > ShootingPieces()) SetShootingPieces(wanted);
}

}  // namespace cosserat
