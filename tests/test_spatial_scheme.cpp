// The Heun (order-2) spatial scheme of the BDF2 shooting stepper against the truth: rest stays
// rest, the order in s against an RK4 run on a fine grid, linear momentum of a free rod. (Its
// exact Jacobian: Bdf2Dynamics.ShootingJacobianMatchesFiniteDifferences, for both schemes.)
#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace cosserat
