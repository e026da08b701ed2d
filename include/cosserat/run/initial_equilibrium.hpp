#pragma once
/// \file
/// The equilibrium a dynamics run of the SE(3) stepper starts from, as the CLI and the Python
/// Stepper find it.

#include <optional>

#include "cosserat/io/problem.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat::run {

/// Puts `stepper` (built for `problem`'s rod and nodes) at rest under `input`'s loads and
/// actuation. A cantilever starts from the statics solver's equilibrium: its continuation in
/// the load keeps to the branch the loads grow along, where the stepper's own Newton solve from
/// a rigid-body guess may settle on a looped one (a wire bent by FL²/EI ≈ 13), and its pieces
/// resolve a rod one shot from the clamp cannot (a payload hanging on a wire, a taut riser);
/// the stepper refines it on its own equations. A column (clamped-clamped, clamped-pinned) starts
/// from the column solver's, followed from the unloaded column. The stepper's own solve runs
/// where the statics solvers fail or do not take the rod, and for free-free ends. The summary
/// counts the work of every attempt; its residual is the last one's. *unstable_directions, when
/// given, receives the statics' count of the start's unstable directions (−1: not counted).
StepSummary InitializeAtStaticEquilibrium(const io::Problem& problem, const StepInput& input,
                                          Bdf2ShootingStepper* stepper,
                                          int* unstable_directions = nullptr);

/// The statics solver's equilibrium of `problem`'s cantilever under `input` (its base pose, loads
/// and actuation, the tip mass's weight added) that InitializeAtStaticEquilibrium starts from;
/// with contact surfaces, where the SE(3) statics fail, the quaternion-FD equilibrium on the same
/// nodes. Empty when none converges or takes the rod. *unstable_directions as above.
std::optional<RodState> StaticEquilibriumToStartFrom(const io::Problem& problem,
                                                     const StepInput& input,
                                                     int* unstable_directions = nullptr);

/// The loads of the clamped rod's statics: the file's, with the tip mass's weight
/// (dynamics.tip_mass) as a dead tip force. A tip force that follows the section cannot take it:
/// the weight is then left out, and the equilibrium is only the stepper's first guess.
StaticLoads WithTipMassWeight(const io::Problem& problem, StaticLoads loads);

/// After a start refused as non_finite: the single-shot statics of the same cantilever under
/// `input` (the tip mass's weight added), when its shot ran away (RodState::RanAway); empty
/// otherwise. The stepper keeps no state of a start it refused, so this is what says why.
std::optional<RodState> RunawayStartState(const io::Problem& problem, const StepInput& input);

}  // namespace cosserat::run
