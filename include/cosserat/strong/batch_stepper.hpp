#pragma once
/// \file
/// M independent rods of one model stepped together on a team of threads, for controllers and
/// learning loops that run many rods at once: each rod is a Bdf2ShootingStepper with its own
/// input per step. Built once; InitializeAtRest and Step allocate nothing, and rod i's state is
/// exactly what a lone stepper fed the same inputs reaches (the threads only share out the rods).

#include <memory>
#include <vector>

#include "cosserat/numerics/thread_team.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

class BatchStepper {
 public:
  /// `count` rods of `model` on `nodes` grid points, on `threads` threads (the caller included).
  BatchStepper(const RodModel& model, int nodes, const Bdf2Options& options, int count,
               int threads);

  /// Every rod at rest under `input` (the same for all). Returns how many converged.
  int InitializeAtRest(const StepInput& input);
  /// The same from an equilibrium found elsewhere on the rods' grid
  /// (Bdf2ShootingStepper::InitializeAtRest with a state).
  int InitializeAtRest(const StepInput& input, const RodState& equilibrium);
  /// Steps rod i under inputs[i] (count of them). Returns how many converged; summary(i) says
  /// how each went. Throws std::invalid_argument, before any rod moves, for an input a rod's
  /// Step would refuse (Bdf2ShootingStepper::RequireValidInput); InitializeAtRest likewise.
  int Step(const StepInput* inputs);

  /// Every rod's run (Bdf2ShootingStepper::Save); allocates.
  std::vector<Bdf2ShootingStepper::Snapshot> Save() const;
  /// Rod i continues from snapshots[i] (count() of them). Throws std::invalid_argument, before
  /// any rod changes, for a wrong count or a snapshot a rod would refuse
  /// (Bdf2ShootingStepper::Restore).
  void Restore(const std::vector<Bdf2ShootingStepper::Snapshot>& snapshots);
  /// Every rod continues from one run, for instance a lone stepper's measured state that a
  /// sampling controller rolls out under count() input sequences; the same checks.
  void RestoreAll(const Bdf2ShootingStepper::Snapshot& snapshot);

  int count() const { return static_cast<int>(rods_.size()); }
  const Bdf2ShootingStepper& rod(int i) const { return *rods_[i]; }
  const StepSummary& summary(int i) const { return summaries_[i]; }

 private:
  /// Runs solve(i) → StepSummary for every rod on the team, keeps the summaries and returns how
  /// many converged.
  template <typename Solve>
  int EachRod(const Solve& solve) {
    auto job = [&](std::size_t i) { summaries_[i] = solve(i); };
    team_.For(rods_.size(), job);
    int converged = 0;
    for (const StepSummary& s : summaries_) converged += s.converged();
    return converged;
  }

  std::vector<std::unique_ptr<Bdf2ShootingStepper>> rods_;
  std::vector<StepSummary> summaries_;
  ThreadTeam team_;
};

}  // namespace cosserat
