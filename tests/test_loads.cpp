// The load interface (loads/): each load's value and frame, and the equivalences that must hold
// whatever the solver — two descriptions of one load give one equilibrium, and the BDF2 stepper's
// rest state agrees with the static solver under a follower load on a turned clamp.
#include <gtest/gtest.h>

#include <cmath>

#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

RodModel SteelWire() {
  return RodModel::Uniform(0.5, CrossSection::Circle(0.002),
                           Material::FromPoissonRatio(200e9, 0.3, 7800));
}

TEST(Loads, EachLoadInItsFrame) {
  const LoadSite site{0.1, 1.0, 0.25};  // unit length, ρA = 0.25 kg/m
  const Vec3 g(0, 0, -9.81);
  EXPECT_EQ(Gravity(g).DistributedForce_W(site), Vec3(0.25 * g));
  EXPECT_EQ(Gravity(g).TipWrench(2.0).dead_W.tail<3>(), Vec3(2.0 * g));
  EXPECT_EQ(DistributedForce(Vec3(1, 2, 3)).DistributedForce_W(site), Vec3(1, 2, 3));
  EXPECT_EQ(DistributedForce(Vec3(1, 2, 3)).TipWrench(1.0).dead_W, Vec6::Zero());
  // Lumped on a piece of 0.3 m with 0.075 kg: the resultants.
  const LoadSite piece{0.1, 0.3, 0.075};
  EXPECT_EQ(DistributedForce(Vec3(1, 2, 3)).DistributedForce_W(piece), 0.3 * Vec3(1, 2, 3));
  EXPECT_EQ(Gravity(g).DistributedForce_W(piece), Vec3(0.075 * g));
  const SplitWrench dead = TipForce(Vec3(1, 0, 0), LoadFrame::kWorld).TipWrench(0);
  const SplitWrench follower = TipMoment(Vec3(0, 2, 0), LoadFrame::kBody).TipWrench(0);
  EXPECT_EQ(dead.dead_W, (Vec6() << 0, 0, 0, 1, 0, 0).finished());
  EXPECT_EQ(dead.follower_B, Vec6::Zero());
  EXPECT_EQ(follower.follower_B, (Vec6() << 0, 2, 0, 0, 0, 0).finished());
  EXPECT_EQ(follower.dead_W, Vec6::Zero());
  // In the tip body frame: Rᵀ dead + follower.
  const Mat3 R = lie::SO3Exp(Vec3(0.3, -0.2, 0.5));
  const Vec6 body = TipWrenchInBody(dead, R);
  EXPECT_LT((body.tail<3>() - R.transpose() * Vec3(1, 0, 0)).norm(), 1e-15);
}

TEST(Loads, TotalsSumEveryLoadOfAProblem) {
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  loads.distributed_force_W = Vec3(0.5, 0, 0);
  loads.tip_force = Vec3(0, 1, 0);
  loads.tip_force_frame = LoadFrame::kBody;
  loads.tip_moment = Vec3(0, 0, 0.2);
  const Vec3 f = TotalDistributedForce_W(loads, {0.0, 1.0, 0.1});
  EXPECT_EQ(f, Vec3(0.5, 0, 0.1 * -9.81));
  const SplitWrench tip = TotalTipWrench(loads, 0.3);  // a 0.3 kg tip body feels gravity
  EXPECT_EQ(tip.follower_B, (Vec6() << 0, 0, 0, 0, 1, 0).finished());
  EXPECT_EQ(tip.dead_W, (Vec6() << 0, 0, 0.2, 0, 0, 0.3 * -9.81).finished());
  // The potential of the distributed dead loads is −f · p.
  EXPECT_DOUBLE_EQ(TotalDistributedPotential(loads, {0.0, 1.0, 0.1}, Vec3(1, 2, 3)),
                   -f.dot(Vec3(1, 2, 3)));
}

TEST(Loads, GravityAndAnEqualDistributedForceGiveOneEquilibrium) {
  // ρA g as gravity and as a distributed force are the same load on a uniform rod: the static
  // equilibria agree to the solve tolerance (1e-10 in EI/L units moves the tip by ~1e-11 L; 1e-9 L
  // leaves room for the two paths' different round-off in the load steps).
  const RodModel rod = SteelWire();
  const double rhoA = 7800 * kPi * 0.002 * 0.002;
  StaticLoads by_gravity, by_force;
  by_gravity.gravity_W = Vec3(-300.0, 0, 0);  // a heavy sag: tip deflection ~0.15 L
  by_force.distributed_force_W = rhoA * by_gravity.gravity_W;
  StaticShootingSolver a(rod, 41), b(rod, 41);
  ASSERT_TRUE(a.Solve(lie::SE3{}, by_gravity).converged());
  ASSERT_TRUE(b.Solve(lie::SE3{}, by_force).converged());
  EXPECT_GT(std::abs(a.state().tip_position_W().x()), 0.05 * rod.length);
  EXPECT_LT((a.state().tip_position_W() - b.state().tip_position_W()).norm(), 1e-9 * rod.length);
}

TEST(Loads, FollowerTipForceOnATurnedClampAtRestMatchesStatics) {
  // A follower tip force on a rod whose clamp is turned 60° about x: the BDF2 stepper's initial
  // equilibrium (its own static solve from a rigid-body guess) is the static solver's. Both solve
  // the same discrete equations (RK4 on the same grid) to 1e-10 in EI/L units; 1e-8 L covers
  // the two tolerances' effect on the tip.
  const RodModel rod = SteelWire();
  lie::SE3 clamp;
  clamp.R = lie::SO3Exp(Vec3(kPi / 3, 0, 0));
  StaticLoads loads;
  loads.tip_force = Vec3(0.8, 0, 0);  // PL²/EI ≈ 0.16 along the tip's body x
  loads.tip_force_frame = LoadFrame::kBody;
  StaticShootingSolver statics(rod, 21);
  ASSERT_TRUE(statics.Solve(clamp, loads).converged());
  Bdf2ShootingStepper stepper(rod, 21);
  StepInput input;
  input.base_pose = clamp;
  input.loads = loads;
  ASSERT_TRUE(stepper.InitializeAtRest(input).converged());
  const Vec3 tip_statics = statics.state().tip_position_W();
  EXPECT_GT((tip_statics - clamp.R.col(2) * rod.length).norm(), 0.01 * rod.length);
  EXPECT_LT((stepper.state().tip_position_W() - tip_statics).norm(), 1e-8 * rod.length);
}

}  // namespace
}  // namespace cosserat
