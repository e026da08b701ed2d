// Behaviour of the static shooting solver: its Jacobian, warm start, load stepping, global
// equilibrium and its handling of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cosserat/lie/so3.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

RodModel SteelRod(double L = 0.5, double r = 0.001) { return testing::SteelRod{L, r}.model(); }
double EIof(const RodModel& m) { return m.section->At(0, {}).stiffness(0, 0); }

lie::SE3 TiltedBase() {
  lie::SE3 g;
  g.R = lie::SO3Exp(Vec3(0.3, -0.2, 0.7));
  g.p = Vec3(0.1, -0.2, 0.3);
  return g;
}

TEST(StaticShooting, JacobianMatchesFiniteDifferences) {
  const RodModel model = SteelRod();
  StaticShootingSolver solver(model, 21);
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);
  loads.tip_force = Vec3(0.1, -0.3, 0.05);
  loads.tip_moment = Vec3(0.0, 0.01, 0.02);
  loads.tip_moment_frame = LoadFrame::kBody;
  const lie::SE3 base = TiltedBase();
  const Vec6 x = (Vec6() << 0.3, -0.5, 0.2, 1.0, -0.4, 0.7).finished();
  const Mat6 J = solver.ResidualJacobian(base, loads, x);
  // Central differences: truncation O(h²) ≈ 1e-10 and round-off O(eps/h) ≈ 1e-10 relative to the
  // entries' scale (order one in the dimensionless variables); 1e-6 relative is the acceptance.
  const double h = 1e-5;
  for (int j = 0; j < 6; ++j) {
    Vec6 xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    const Vec6 fd = (solver.Residual(base, loads, xp) - solver.Residual(base, loads, xm)) / (2 * h);
    EXPECT_LT((fd - J.col(j)).norm(), 1e-6 * std::max(1.0, J.col(j).norm())) << "column " << j;
  }
}

TEST(StaticShooting, GlobalEquilibriumOfBaseReaction) {
  const RodModel model = SteelRod();
  StaticShootingSolver solver(model, 41);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  loads.distributed_force_W = Vec3(0.05, 0, 0);
  loads.tip_force = Vec3(0.2, 0.1, -0.3);
  const lie::SE3 base = TiltedBase();
  ASSERT_TRUE(solver.Solve(base, loads).converged());
  const double rhoA = model.section->At(0, {}).mass(5, 5);
  const Vec3 external = rhoA * model.length * loads.gravity_W +
                        model.length * loads.distributed_force_W + loads.tip_force;
  const Vec6 reaction = solver.state().BaseReaction_W();
  // n_W' = −f is constant along s, which RK4 integrates exactly; the only error is the solver's
  // residual (1e-10 of EI/L²) and round-off.
  EXPECT_LT((reaction.tail<3>() + external).norm(), 1e-9 * external.norm());
}

TEST(StaticShooting, WarmStartReusesSolution) {
  const RodModel model = SteelRod();
  const double EI = EIof(model);
  StaticShootingSolver warm(model, 41);
  StaticLoads loads;
  loads.tip_force = Vec3(-2.0 * EI / 0.25, 0, 0);  // alpha = 2
  ASSERT_TRUE(warm.Solve(lie::SE3{}, loads).converged());
  loads.tip_force *= 1.01;
  const auto s_warm = warm.Solve(lie::SE3{}, loads);
  ASSERT_TRUE(s_warm.converged());
  EXPECT_TRUE(s_warm.warm_started);

  StaticShootingSolver cold(model, 41);
  const auto s_cold = cold.Solve(lie::SE3{}, loads);
  ASSERT_TRUE(s_cold.converged());
  EXPECT_FALSE(s_cold.warm_started);
  EXPECT_LT(s_warm.shots, s_cold.shots);
  // Both satisfy the same discrete equations to 1e-10 (dimensionless): the tips agree to the
  // conditioning of the problem times that, far below 1e-8 L.
  EXPECT_LT((warm.state().tip_position_W() - cold.state().tip_position_W()).norm(), 1e-8 * 0.5);
}

TEST(StaticShooting, LoadSteppingRescuesAStarvedSolve) {
  // With only 3 LM steps allowed per solve a large tip load cannot converge in one go; the
  // continuation in the load must still reach the elastica answer (alpha = 10, deflection
  // 0.8106090249 L from the reference table).
  const RodModel model = SteelRod(1.0, 0.005);
  StaticShootingOptions opt;
  opt.max_iterations = 4;        // TinySolver counts the first evaluation: 3 steps
  opt.max_load_increment = 100;  // let the direct attempt happen (and fail)
  StaticShootingSolver solver(model, 41, opt);
  StaticLoads loads;
  loads.tip_force = Vec3(-10.0 * EIof(model), 0, 0);
  const auto summary = solver.Solve(lie::SE3{}, loads);
  ASSERT_TRUE(summary.converged()) << ToString(summary.status);
  EXPECT_GT(summary.load_steps, 1);
  EXPECT_NEAR(-solver.state().tip_position_W().x(), 0.8106090249, 1e-3);
}

TEST(StaticShooting, FailureIsReportedNotHidden) {
  // Load stepping off and one iteration: the status must say so, not claim convergence.
  const RodModel model = SteelRod();
  StaticShootingOptions opt;
  opt.max_iterations = 1;
  opt.load_stepping = false;
  StaticShootingSolver solver(model, 41, opt);
  StaticLoads loads;
  loads.tip_force = Vec3(-10.0 * EIof(model) / 0.25, 0, 0);
  const auto summary = solver.Solve(lie::SE3{}, loads);
  EXPECT_FALSE(summary.converged());
  EXPECT_EQ(summary.status, SolveStatus::kMaxIterations);
  EXPECT_GT(summary.residual, opt.tolerance);
}

// A tip moment that curls the rod into coils tighter than its grid (41 nodes, κ h ≈ 2.9 rad at
// the last level): the continuation stops short. The state it leaves is that level's
// equilibrium: its tip carries the level's moment, μ M, to the intermediate levels' tolerance
// (1e-6 of EI/L), while the residual reported is the one against the whole load. The state
// written was once the level's unknowns shot under the whole moment, a shape of no load at all.
TEST(StaticShooting, LoadStepsThatStopShortLeaveTheLevelTheyReached) {
  const RodModel model = SteelRod();
  StaticShootingSolver solver(model, 41);
  StaticLoads loads;
  loads.tip_moment = Vec3(0, 100.0, 0);  // N·m: κ = M/EI = 637 /m, coils of 1.6 mm radius
  loads.tip_force = Vec3(-0.2, 0, 0);     // N, with the weight: the cantilever example's loads
  loads.gravity_W = Vec3(-9.81, 0, 0);
  const StaticShootingSummary summary = solver.Solve(lie::SE3{}, loads);
  ASSERT_EQ(summary.status, SolveStatus::kLoadSteppingFailed);
  const double mu = summary.load_fraction;
  ASSERT_GT(mu, 0.0);
  ASSERT_LT(mu, 1.0);
  const RodState& state = solver.state();
  const Vec3 moment_W = state.tip_rotation_WB() * state.wrench_B.back().head<3>();
  const double unit = EIof(model) / model.length;
  EXPECT_LT((moment_W - mu * loads.tip_moment).norm(), 1e-6 * unit)
      << moment_W.transpose() << " at load fraction " << mu;
  EXPECT_GT(summary.residual, 0.1);  // the whole moment is not balanced
}

TEST(StaticShooting, FollowerMomentEqualsDeadMomentForPlanarBending) {
  // A moment about y stays about y as the rod bends in the x–z plane, so dead and follower
  // moments give the same circle.
  const RodModel model = SteelRod();
  StaticShootingSolver dead(model, 41), follower(model, 41);
  StaticLoads loads;
  loads.tip_moment = Vec3(0, 1.5 * kPi * EIof(model) / model.length, 0);
  ASSERT_TRUE(dead.Solve(lie::SE3{}, loads).converged());
  loads.tip_moment_frame = LoadFrame::kBody;
  ASSERT_TRUE(follower.Solve(lie::SE3{}, loads).converged());
  EXPECT_LT((dead.state().tip_position_W() - follower.state().tip_position_W()).norm(), 1e-9);
}

TEST(StaticShooting, FollowerForceDiffersFromDeadForce) {
  // A follower force stays perpendicular to the tip tangent, so the rod curls further than under
  // the same dead load: the tip angle is larger.
  const RodModel model = SteelRod();
  StaticShootingSolver dead(model, 41), follower(model, 41);
  StaticLoads loads;
  loads.tip_force = Vec3(-1.0 * EIof(model) / 0.25, 0, 0);
  ASSERT_TRUE(dead.Solve(lie::SE3{}, loads).converged());
  loads.tip_force_frame = LoadFrame::kBody;
  ASSERT_TRUE(follower.Solve(lie::SE3{}, loads).converged());
  auto tip_angle = [](const StaticShootingSolver& s) {
    const Vec3 t = s.state().tip_rotation_WB().col(2);
    return std::atan2(-t.x(), t.z());
  };
  EXPECT_GT(tip_angle(follower), tip_angle(dead) + 0.01);
}

TEST(StaticShooting, NonFiniteInputIsAStatusNotAConvergedAnswer) {
  StaticShootingSolver solver(SteelRod(), 41);
  StaticLoads loads;
  loads.tip_force = Vec3(0, std::nan(""), 0);
  auto summary = solver.Solve(lie::SE3{}, loads);  // cold
  EXPECT_EQ(summary.status, SolveStatus::kNonFinite);
  loads.tip_force = Vec3(-0.1, 0, 0);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  loads.tip_moment = Vec3(0, std::numeric_limits<double>::infinity(), 0);
  summary = solver.Solve(lie::SE3{}, loads);  // warm
  EXPECT_EQ(summary.status, SolveStatus::kNonFinite);
  EXPECT_FALSE(summary.converged());
  // The solver still warm-starts from the last good solution afterwards.
  loads.tip_moment.setZero();
  loads.tip_force = Vec3(-0.101, 0, 0);
  summary = solver.Solve(lie::SE3{}, loads);
  EXPECT_TRUE(summary.converged());
  EXPECT_TRUE(summary.warm_started);
}

// A "rotation" that is not one (2·I) used to integrate a rod stretched twice over and call it
// converged (tip at z = 2L): refused, as a matrix off by 1e-5 is; one typed to 7 digits is not.
TEST(StaticShooting, RefusesABaseThatIsNotARotation) {
  StaticShootingSolver solver(SteelRod(), 41);
  lie::SE3 base;
  base.R = 2.0 * Mat3::Identity();
  EXPECT_THROW(solver.Solve(base, StaticLoads{}), std::invalid_argument);
  base.R = Mat3::Identity();
  base.R(0, 1) = 1e-5;
  EXPECT_THROW(solver.Solve(base, StaticLoads{}), std::invalid_argument);
  base.R(0, 1) = 1e-7;
  EXPECT_TRUE(solver.Solve(base, StaticLoads{}).converged());
}

TEST(StaticShooting, RejectsBadModelAndOptions) {
  RodModel bad = SteelRod();
  bad.length = -0.5;
  EXPECT_THROW(StaticShootingSolver(bad, 41), std::invalid_argument);
  bad = SteelRod();
  bad.length = std::nan("");
  EXPECT_THROW(StaticShootingSolver(bad, 41), std::invalid_argument);
  EXPECT_THROW(StaticShootingSolver(SteelRod(), 1), std::invalid_argument);
  StaticShootingOptions opt;
  opt.tolerance = -1;
  EXPECT_THROW(StaticShootingSolver(SteelRod(), 41, opt), std::invalid_argument);
}

}  // namespace
}  // namespace cosserat
