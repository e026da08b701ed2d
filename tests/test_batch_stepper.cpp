// BatchStepper: rods stepped together on a team of threads reach exactly the states lone
// steppers reach with the same inputs (the threads only share out the rods), for any number of
// threads; ThreadTeam runs every index once.
#include <gtest/gtest.h>

#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosserat/numerics/thread_team.hpp"
#include "cosserat/strong/batch_stepper.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

TEST(ThreadTeam, RunsEveryIndexOnceOnEveryCall) {
  ThreadTeam team(3);
  std::vector<std::atomic<int>> hits(1000);
  for (int call = 0; call < 50; ++call) {
    auto job = [&](std::size_t i) { hits[i].fetch_add(1); };
    team.For(hits.size(), job);
  }
  for (const auto& h : hits) EXPECT_EQ(h.load(), 50);
}

TEST(ThreadTeam, AJobsExceptionReachesTheCallerAndTheTeamStaysUsable) {
  // A throwing job on a worker thread would call std::terminate; it is rethrown by Run, once
  // every index has run, and the next call runs normally.
  ThreadTeam team(3);
  std::vector<std::atomic<int>> hits(100);
  auto throwing = [&](std::size_t i) {
    hits[i].fetch_add(1);
    if (i % 10 == 7) throw std::runtime_error("index " + std::to_string(i));
  };
  EXPECT_THROW(team.For(hits.size(), throwing), std::runtime_error);
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
  auto counting = [&](std::size_t i) { hits[i].fetch_add(1); };
  team.For(hits.size(), counting);
  for (const auto& h : hits) EXPECT_EQ(h.load(), 2);
}

/// Tip force of rod i at step k: each rod its own load history.
Vec3 TipForce(int i, int k) { return Vec3(-0.05 - 0.01 * i, 0.002 * k * (i % 3), 0.0); }

TEST(BatchStepper, RodsReachExactlyWhatLoneSteppersReach) {
  const testing::SteelRod rod{0.5, 0.001};
  const int M = 8, steps = 30;
  Bdf2Options opt;
  opt.dt = 2e-3;
  // A million threads asked for: the team is never larger than the rods (starting them all
  // would run the system out of threads).
  for (int threads : {1, 2, 3, 1000000}) {
    SCOPED_TRACE(threads);
    BatchStepper batch(rod.model(), 21, opt, M, threads);
    StepInput rest;
    rest.loads.gravity_W = Vec3(-9.81, 0, 0);
    ASSERT_EQ(batch.InitializeAtRest(rest), M);
    std::vector<StepInput> inputs(M, rest);
    std::vector<Bdf2ShootingStepper> lone(M, Bdf2ShootingStepper(rod.model(), 21, opt));
    for (auto& s : lone) ASSERT_TRUE(s.InitializeAtRest(rest).converged());
    for (int k = 0; k < steps; ++k) {
      for (int i = 0; i < M; ++i) inputs[i].loads.tip_force = TipForce(i, k);
      ASSERT_EQ(batch.Step(inputs.data()), M);
      for (int i = 0; i < M; ++i) ASSERT_TRUE(lone[i].Step(inputs[i]).converged());
    }
    for (int i = 0; i < M; ++i) {
      // Bitwise: the same operations on the same data, whichever thread ran them.
      EXPECT_EQ(batch.rod(i).state().tip_position_W(), lone[i].state().tip_position_W()) << i;
      EXPECT_EQ(batch.rod(i).state().twist_B.back(), lone[i].state().twist_B.back()) << i;
    }
  }
}

TEST(BatchStepper, AnInputOneRodRefusesIsThrownBeforeAnyRodMoves) {
  // A base "rotation" 2 I for rod 3: std::invalid_argument on the caller's thread (from a worker
  // it ended the process), and every rod where it was.
  const testing::SteelRod rod{0.5, 0.001};
  Bdf2Options opt;
  opt.dt = 2e-3;
  BatchStepper batch(rod.model(), 21, opt, 4, 2);
  StepInput rest;
  rest.loads.gravity_W = Vec3(-9.81, 0, 0);
  ASSERT_EQ(batch.InitializeAtRest(rest), 4);
  std::vector<StepInput> inputs(4, rest);
  inputs[3].base_pose.R = 2.0 * Mat3::Identity();
  EXPECT_THROW(batch.Step(inputs.data()), std::invalid_argument);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(batch.rod(i).time(), 0.0) << i;
  StepInput bad_rest = rest;
  bad_rest.base_pose.R = 2.0 * Mat3::Identity();
  EXPECT_THROW(batch.InitializeAtRest(bad_rest), std::invalid_argument);
  inputs[3] = rest;
  EXPECT_EQ(batch.Step(inputs.data()), 4);
}

/// M rods of the 0.5 m steel rod (21 nodes, dt 2 ms) at rest under gravity along −x.
struct RestingBatch {
  testing::SteelRod rod{0.5, 0.001};
  Bdf2Options options = [] {
    Bdf2Options o;
    o.dt = 2e-3;
    return o;
  }();
  StepInput rest = [] {
    StepInput r;
    r.loads.gravity_W = Vec3(-9.81, 0, 0);
    return r;
  }();
  BatchStepper batch;
  explicit RestingBatch(int count) : batch(rod.model(), 21, options, count, 2) {}

  /// Steps k0 … k0 + steps − 1 under TipForce; every rod's tip after the last.
  std::vector<Vec3> Run(int k0, int steps) {
    std::vector<StepInput> inputs(batch.count(), rest);
    for (int k = k0; k < k0 + steps; ++k) {
      for (int i = 0; i < batch.count(); ++i) inputs[i].loads.tip_force = TipForce(i, k);
      EXPECT_EQ(batch.Step(inputs.data()), batch.count());
    }
    std::vector<Vec3> tips;
    for (int i = 0; i < batch.count(); ++i) tips.push_back(batch.rod(i).state().tip_position_W());
    return tips;
  }
};

TEST(BatchStepper, ARestoredBatchRepeatsItsRunBitForBit) {
  // Saved after 10 steps, the next 15 are the truth; restored, the same 15 must repeat them
  // exactly (the snapshot is the whole run: history, Jacobian factors, automatic pieces).
  RestingBatch b(4);
  ASSERT_EQ(b.batch.InitializeAtRest(b.rest), 4);
  b.Run(0, 10);
  const std::vector<Bdf2ShootingStepper::Snapshot> saved = b.batch.Save();
  const std::vector<Vec3> first = b.Run(10, 15);
  b.batch.Restore(saved);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(b.batch.rod(i).time(), saved[i].time) << i;
  const std::vector<Vec3> again = b.Run(10, 15);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(first[i], again[i]) << i;
}

TEST(BatchStepper, RodsRolledOutFromALoneSteppersSnapshotContinueItsRun) {
  // A sampling controller's rollouts: every rod from one measured state. Rod i under rod i's
  // inputs must reach exactly what the lone stepper, never interrupted, reaches under them.
  RestingBatch b(3);
  std::vector<Bdf2ShootingStepper> lone(3, Bdf2ShootingStepper(b.rod.model(), 21, b.options));
  StepInput input = b.rest;
  for (auto& s : lone) ASSERT_TRUE(s.InitializeAtRest(b.rest).converged());
  for (int k = 0; k < 12; ++k) {  // the measured past: rod 0's inputs, in every lone stepper
    input.loads.tip_force = TipForce(0, k);
    for (auto& s : lone) ASSERT_TRUE(s.Step(input).converged());
  }
  b.batch.RestoreAll(lone[0].Save());
  for (int k = 12; k < 30; ++k)
    for (int i = 0; i < 3; ++i) {
      input.loads.tip_force = TipForce(i, k);
      ASSERT_TRUE(lone[i].Step(input).converged());
    }
  const std::vector<Vec3> rolled = b.Run(12, 18);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(rolled[i], lone[i].state().tip_position_W()) << i;
}

TEST(BatchStepper, ASnapshotOneRodRefusesChangesNoRod) {
  // A wrong count, or one snapshot of another grid among good ones: std::invalid_argument and
  // every rod where it was (time and tip).
  RestingBatch b(3);
  ASSERT_EQ(b.batch.InitializeAtRest(b.rest), 3);
  std::vector<Bdf2ShootingStepper::Snapshot> saved = b.batch.Save();
  const std::vector<Vec3> tips = b.Run(0, 5);
  EXPECT_THROW(b.batch.Restore({saved[0], saved[1]}), std::invalid_argument);
  Bdf2ShootingStepper other_grid(b.rod.model(), 31, b.options);
  ASSERT_TRUE(other_grid.InitializeAtRest(b.rest).converged());
  saved[2] = other_grid.Save();
  EXPECT_THROW(b.batch.Restore(saved), std::invalid_argument);
  EXPECT_THROW(b.batch.RestoreAll(saved[2]), std::invalid_argument);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(b.batch.rod(i).time(), 5 * b.options.dt, 1e-15) << i;
    EXPECT_EQ(b.batch.rod(i).state().tip_position_W(), tips[i]) << i;
  }
}

TEST(BatchStepper, ANonFiniteInputIsThatRodsStatusAlone) {
  // NaN in one rod's tip force, or in another's tendon tension: those two rods report
  // non_finite and stay where they were, the others step (the batch used to throw for the
  // tension, and no rod moved). A NaN base position at rest is non_finite too (it was
  // "converged", with a NaN tip), and leaves the run before it as it was.
  RestingBatch b(4);
  ASSERT_EQ(b.batch.InitializeAtRest(b.rest), 4);
  std::vector<StepInput> inputs(4, b.rest);
  inputs[1].loads.tip_force.x() = std::numeric_limits<double>::quiet_NaN();
  inputs[2].actuation.tendon_tension[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(b.batch.Step(inputs.data()), 2);
  for (int i = 0; i < 4; ++i) {
    const bool bad = i == 1 || i == 2;
    EXPECT_EQ(b.batch.summary(i).status, bad ? SolveStatus::kNonFinite : SolveStatus::kConverged);
    EXPECT_EQ(b.batch.rod(i).time(), bad ? 0.0 : b.options.dt) << i;
  }
  StepInput nan_base = b.rest;
  nan_base.base_pose.p.x() = std::numeric_limits<double>::quiet_NaN();
  Bdf2ShootingStepper lone(b.rod.model(), 21, b.options);
  ASSERT_TRUE(lone.InitializeAtRest(b.rest).converged());
  ASSERT_TRUE(lone.Step(b.rest).converged());
  EXPECT_EQ(lone.InitializeAtRest(nan_base).status, SolveStatus::kNonFinite);
  EXPECT_EQ(lone.time(), b.options.dt);
  EXPECT_TRUE(lone.Step(b.rest).converged());
  EXPECT_EQ(b.batch.InitializeAtRest(nan_base), 0);
}

TEST(BatchStepper, NoThreadsIsAnError) {
  const testing::SteelRod rod{0.5, 0.001};
  EXPECT_THROW(BatchStepper(rod.model(), 21, Bdf2Options{}, 4, 0), std::invalid_argument);
}

}  // namespace
}  // namespace cosserat
