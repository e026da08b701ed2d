// The spatial schemes of the BDF2 shooting stepper besides RK4 against the truth: Heun (order
// 2) and RK4 across pairs of segments (order 4, the default). Rest stays rest, the order in s
// against an RK4 run on a fine grid, linear momentum of a free rod. (Their exact Jacobians:
// Bdf2Dynamics.ShootingJacobianMatchesFiniteDifferences, for every scheme.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "../bench/peer_rod.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {
namespace {

using bench::PeerPreload;
using bench::PeerRod;

Bdf2Options Options(SpatialScheme scheme) {
  Bdf2Options opt;
  opt.spatial_scheme = scheme;
  return opt;
}

TEST(SpatialScheme, HeunRodAtRestStaysThere) {
  Bdf2ShootingStepper stepper(PeerRod(), 40, Options(SpatialScheme::kHeun));
  const StepInput in = PeerPreload();
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  const Vec3 tip0 = stepper.state().tip_position_W();
  // The equilibrium solves the same Heun equations with zero rates, and BDF2 of a constant
  // history is exactly zero: only round-off moves the tip.
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(stepper.Step(in).converged()) << i;
  EXPECT_LT((stepper.state().tip_position_W() - tip0).norm(), 1e-10 * 0.5);
}

// Tip positions every step over the first 0.2 s after the release of the peer problem.
std::vector<Vec3> ReleaseTrajectory(int nodes, SpatialScheme scheme) {
  Bdf2ShootingStepper stepper(PeerRod(), nodes, Options(scheme));
  StepInput in = PeerPreload();
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  std::vector<Vec3> tip;
  for (int i = 0; i < 100; ++i) {
    EXPECT_TRUE(stepper.Step(in).converged()) << nodes << " step " << i;
    tip.push_back(stepper.state().tip_position_W());
  }
  return tip;
}

double MaxDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double m = 0;
  for (size_t k = 0; k < a.size() && k < b.size(); ++k) m = std::max(m, (a[k] - b[k]).norm());
  return m;
}

// Same dt, so the time discretisation is common to all runs and cancels: what is left is the
// spatial error. The reference is RK4 at 161 nodes (its own spatial error ~(1/4)⁴ of RK4 at 41,
// 3.5e-6 mm over 25 s on this problem, far below Heun's).
TEST(SpatialScheme, HeunIsSecondOrderInS) {
  const std::vector<Vec3> ref = ReleaseTrajectory(161, SpatialScheme::kRk4);
  const double e20 = MaxDistance(ReleaseTrajectory(21, SpatialScheme::kHeun), ref);
  const double e40 = MaxDistance(ReleaseTrajectory(41, SpatialScheme::kHeun), ref);
  const double e80 = MaxDistance(ReleaseTrajectory(81, SpatialScheme::kHeun), ref);
  // Measured: 0.72, 0.184, 0.0462 mm (orders 1.97, 2.00); RK4 at 41 nodes 8e-5 mm.
  // Order 2: ratios of 4 per halving of the segment length. At 20 segments λh ≈ 0.35 (λL ≈ 7 at
  // dt = 2 ms), where the next term of the error still shows, hence the looser first bound.
  EXPECT_NEAR(std::log2(e20 / e40), 2.0, 0.3) << e20 << " " << e40 << " " << e80;
  EXPECT_NEAR(std::log2(e40 / e80), 2.0, 0.15) << e20 << " " << e40 << " " << e80;
  // And RK4 at 41 nodes is far closer than Heun at 41 (order 4 against 2).
  EXPECT_LT(MaxDistance(ReleaseTrajectory(41, SpatialScheme::kRk4), ref), 1e-2 * e40);
}

// As Bdf2FreeFree.LinearMomentumConservedToSolverTolerance, with Heun: the momentum quadrature
// uses the scheme's own weights (h/2, h/2), the same that sum n_W' in the shot, so the BDF2
// recurrence of momentum holds to the residual tolerance whatever the scheme.
TEST(SpatialScheme, HeunConservesTheLinearMomentumOfAFreeRod) {
  Bdf2Options opt = Options(SpatialScheme::kHeun);
  opt.ends = EndConditions::kFreeFree;
  opt.dt = 1e-3;
  Bdf2ShootingStepper stepper(PeerRod(), 41, opt);
  StepInput in;
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  ASSERT_TRUE(stepper.Step(in).converged());  // at rest (the first step is backward Euler)
  in.loads.tip_force = Vec3(0.01, 0.02, 0.005);
  const Vec3 impulse = in.loads.tip_force * opt.dt;
  ASSERT_TRUE(stepper.Step(in).converged());
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(stepper.Step(StepInput{}).converged());
  const Vec3 a = stepper.Momentum().linear_W;
  // BDF2 spreads the impulse over the first steps; 20 steps on, < 1e-9 of it is still to come.
  EXPECT_LT((a - impulse).norm(), 1e-7 * impulse.norm());
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(stepper.Step(StepInput{}).converged());
  // RK4's measured drift over 1000 steps at tolerance 1e-10 is 1.9e-8; the same bound.
  EXPECT_LT((stepper.Momentum().linear_W - a).norm(), 1e-7 * a.norm());
}

// Every node's position every step over the first 0.2 s after the release of the peer problem.
std::vector<std::vector<Vec3>> ReleaseShapes(int nodes, SpatialScheme scheme, int* shot_steps) {
  Bdf2ShootingStepper stepper(PeerRod(), nodes, Options(scheme));
  *shot_steps = stepper.shot_steps();
  StepInput in = PeerPreload();
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  std::vector<std::vector<Vec3>> shapes;
  for (int i = 0; i < 100; ++i) {
    EXPECT_TRUE(stepper.Step(in).converged()) << nodes << " step " << i;
    shapes.push_back(stepper.state().position_W);
  }
  return shapes;
}

// The largest distance of a node of `coarse` from the same point of `fine` (whose grid has
// `ratio` segments for each of coarse's), over all nodes and steps.
double MaxNodeDistance(const std::vector<std::vector<Vec3>>& coarse,
                       const std::vector<std::vector<Vec3>>& fine, int ratio) {
  double m = 0;
  for (size_t k = 0; k < coarse.size(); ++k)
    for (size_t i = 0; i < coarse[k].size(); ++i)
      m = std::max(m, (coarse[k][i] - fine[k][ratio * i]).norm());
  return m;
}

// As HeunIsSecondOrderInS, for RK4 across pairs, on every node: the nodes a pair steps over
// come from RK4's dense output, whose local error is O(h⁴) like the pair's own global error, so
// they converge at order 4 too. The pairs form where the pair's exponent 2hλ ≤ ½ (λL ≈ 7 at
// dt = 2 ms): at 41 nodes and finer. Reference: RK4 at 321 nodes, whose spatial error is
// (1/8)⁴ of RK4 at 41 nodes (8e-5 mm), far below the pairs' errors.
TEST(SpatialScheme, Rk4PairsIsFourthOrderInSAtEveryNode) {
  int steps = 0;
  const auto ref = ReleaseShapes(321, SpatialScheme::kRk4, &steps);
  const auto s40 = ReleaseShapes(41, SpatialScheme::kRk4Pairs, &steps);
  EXPECT_EQ(steps, 20);  // every segment in a pair
  const auto s80 = ReleaseShapes(81, SpatialScheme::kRk4Pairs, &steps);
  EXPECT_EQ(steps, 40);
  const auto s160 = ReleaseShapes(161, SpatialScheme::kRk4Pairs, &steps);
  const double e40 = MaxNodeDistance(s40, ref, 8), e80 = MaxNodeDistance(s80, ref, 4),
               e160 = MaxNodeDistance(s160, ref, 2);
  std::printf("rk4 pairs, every node: %.3g %.3g %.3g mm\n", 1e3 * e40, 1e3 * e80, 1e3 * e160);
  // Order 4: ratios of 16 per halving. ±0.3 in the order allows the next term of the error at
  // the coarsest grid (as for Heun) and the solver's tolerance, which is ~1e-8 mm here.
  EXPECT_NEAR(std::log2(e40 / e80), 4.0, 0.3) << e40 << " " << e80 << " " << e160;
  EXPECT_NEAR(std::log2(e80 / e160), 4.0, 0.3) << e40 << " " << e80 << " " << e160;
  // At Heun's cost, far closer than Heun on the same grid.
  const auto heun = ReleaseShapes(41, SpatialScheme::kHeun, &steps);
  EXPECT_LT(e40, 1e-2 * MaxNodeDistance(heun, ref, 8));
}

// 40 nodes: 39 segments, so 19 pairs and one segment alone (RK4 on it); a pair never straddles
// a junction of multiple shooting, and a section breakpoint is never stepped over.
TEST(SpatialScheme, Rk4PairsLeaveASegmentAloneWhereTheyMust) {
  EXPECT_EQ(Bdf2ShootingStepper(PeerRod(), 40, Options(SpatialScheme::kRk4Pairs)).shot_steps(), 20);
  // A step the rod bends along too fast for a pair (2hλ > ½): dt = 0.1 ms gives λL ≈ 39.
  Bdf2Options fast = Options(SpatialScheme::kRk4Pairs);
  fast.dt = 1e-4;
  EXPECT_EQ(Bdf2ShootingStepper(PeerRod(), 41, fast).shot_steps(), 40);
  // A breakpoint at s = 0.25 m, on node 20 of 41: the pairs (0–1, …, 18–19) and (20–21, …) fit
  // around it; at s = 0.2375 m (node 19) the pair 18–19 / 19–20 would step over it.
  for (double cut : {0.25, 0.2375}) {
    RodModel rod = PeerRod();  // a band of factor 1: the same rod, with a breakpoint at `cut`
    rod.section = std::make_shared<BandedSection>(
        rod.section, std::vector<BandedSection::Band>{{cut, 0.5, 1.0}});
    Bdf2ShootingStepper stepper(rod, 41, Options(SpatialScheme::kRk4Pairs));
    EXPECT_EQ(stepper.shot_steps(), cut == 0.25 ? 20 : 21) << cut;
  }
}

// The pairs' stage slots depend on dt: a snapshot is refused by a stepper that pairs otherwise
// (here none at dt = 0.1 ms), and one that asks for more pieces than there would be steps keeps
// every segment alone instead of refusing them.
TEST(SpatialScheme, Rk4PairsPlanIsPartOfASnapshotAndYieldsToExplicitPieces) {
  Bdf2Options paired = Options(SpatialScheme::kRk4Pairs), fast = paired;
  fast.dt = 1e-4;
  Bdf2ShootingStepper a(PeerRod(), 41, paired), b(PeerRod(), 41, fast);
  ASSERT_TRUE(a.InitializeAtRest(PeerPreload()).converged());
  EXPECT_THROW(b.Restore(a.Save()), std::invalid_argument);
  Bdf2Options pieces = paired;
  pieces.shooting_segments = 30;  // more than the 20 steps of the pairs
  Bdf2ShootingStepper c(PeerRod(), 41, pieces);
  EXPECT_EQ(c.shot_steps(), 40);
  EXPECT_TRUE(c.InitializeAtRest(PeerPreload()).converged());
}

// As HeunConservesTheLinearMomentumOfAFreeRod, with RK4 across pairs: the quadrature is RK4's
// weights over each pair, the same that sum n_W' in the shot.
TEST(SpatialScheme, Rk4PairsConserveTheLinearMomentumOfAFreeRod) {
  Bdf2Options opt = Options(SpatialScheme::kRk4Pairs);
  opt.ends = EndConditions::kFreeFree;
  opt.dt = 1e-3;
  Bdf2ShootingStepper stepper(PeerRod(), 81, opt);
  ASSERT_EQ(stepper.shot_steps(), 40);
  StepInput in;
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  ASSERT_TRUE(stepper.Step(in).converged());
  in.loads.tip_force = Vec3(0.01, 0.02, 0.005);
  const Vec3 impulse = in.loads.tip_force * opt.dt;
  ASSERT_TRUE(stepper.Step(in).converged());
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(stepper.Step(StepInput{}).converged());
  const Vec3 a = stepper.Momentum().linear_W;
  EXPECT_LT((a - impulse).norm(), 1e-7 * impulse.norm());  // the bounds of the Heun test
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(stepper.Step(StepInput{}).converged());
  EXPECT_LT((stepper.Momentum().linear_W - a).norm(), 1e-7 * a.norm());
}

}  // namespace
}  // namespace cosserat
