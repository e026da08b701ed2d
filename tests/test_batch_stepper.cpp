// BatchStepper: rods stepped together on a team of threads reach exactly the states lone
// steppers reach with the same inputs (the threads only share out the rods), for any number of
// threads; ThreadTeam runs every index once.
#include <gtest/gtest.h>

#include <atomic>
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

TEST(BatchStepper, NoThreadsIsAnError) {
  const testing::SteelRod rod{0.5, 0.001};
  EXPECT_THROW(BatchStepper(rod.model(), 21, Bdf2Options{}, 4, 0), std::invalid_argument);
}

}  // namespace
}  // namespace cosserat
