// Growth at the tip in the BDF2 stepper (eversion robots): material behind the tip stays where it
// is, a free body stays straight with its tip at L(t), and slow growth under gravity ends on the
// static cantilever of the final length.
#include <gtest/gtest.h>

#include <cmath>

#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

RodModel SteelRod(double length, double relaxation_time) {
  const CrossSection sec = CrossSection::Circle(0.001);
  return RodModel::Uniform(length, sec, testing::DampedSteel(sec, relaxation_time));
}

TEST(GrowthDynamics, FreeBodyUnderAxialTipTensionStaysStraightWithItsTipAtLOfT) {
  // A follower tip force P along the tangent (like an eversion robot's p·A) stretches the body
  // uniformly by ε = P/EA; each material point s then sits at s (1 + ε) on the axis, before and
  // after every growth step. Exact in the model, so only the solver tolerance (1e-10 of EI/L²,
  // i.e. ~1e-10 N of force and ~1e-20 of strain) and round-off remain: 1e-12 L.
  const double P = 50.0;
  RodModel model = SteelRod(0.2, 0.0);
  const double EA = 200e9 * CrossSection::Circle(0.001).area, eps = P / EA;
  Bdf2Options opt;
  opt.dt = 2e-3;
  Bdf2ShootingStepper stepper(model, 17, opt);
  // The default scheme pairs the 16 segments (2hλ ≈ 0.43); a grown segment keeps to itself, and
  // the old ones keep their pairs (their history is at the pairs' stages): 8 + 20 steps at the end.
  EXPECT_EQ(stepper.shot_steps(), 8);
  StepInput in;
  in.loads.tip_force = Vec3(0, 0, P);
  in.loads.tip_force_frame = LoadFrame::kBody;
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  for (int g = 0; g < 20; ++g) {
    model.length += 0.01;
    stepper.Grow(model, 1);
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(stepper.Step(in).converged()) << g << " " << k;
    const RodState& st = stepper.state();
    for (int i = 0; i < st.size(); ++i) {
      EXPECT_LT(st.position_W[i].head<2>().norm(), 1e-12 * model.length) << g << " node " << i;
      EXPECT_NEAR(st.position_W[i].z(), st.s[i] * (1 + eps), 1e-12 * model.length) << i;
    }
    EXPECT_NEAR(st.tip_position_W().z(), model.length * (1 + eps), 1e-12 * model.length);
  }
  EXPECT_NEAR(model.length, 0.4, 1e-12);
  EXPECT_EQ(stepper.shot_steps(), 28);
}

TEST(GrowthDynamics, SlowGrowthUnderGravityEndsOnTheStaticCantileverOfTheFinalLength) {
  // Horizontal, damped (τ = 20 ms: ζ ≈ 0.35 on the first mode), grown 0.3 → 0.5 m at 1 cm per
  // 50 ms, then left to settle 1 s (e^{-ζωt} < 1e-5). Acceptance: 1e-3 L of the static solution.
  RodModel model = SteelRod(0.3, 2e-2);
  Bdf2Options opt;
  opt.dt = 2e-3;
  Bdf2ShootingStepper stepper(model, 25, opt);
  StepInput in;
  in.base_pose.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // rod along +x
  in.loads.gravity_W = Vec3(0, 0, -9.81);
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  for (int g = 0; g < 20; ++g) {
    model.length += 0.01;
    stepper.Grow(model, 1);
    for (int k = 0; k < 25; ++k) ASSERT_TRUE(stepper.Step(in).converged()) << g << " " << k;
  }
  for (int k = 0; k < 500; ++k) ASSERT_TRUE(stepper.Step(in).converged()) << k;
  StaticShootingSolver statics(model, 41);
  ASSERT_TRUE(statics.Solve(in.base_pose, in.loads).converged());
  const Vec3 tip = statics.state().tip_position_W();
  EXPECT_GT(-tip.z(), 0.02 * model.length);  // a sag worth matching
  EXPECT_LT((stepper.state().tip_position_W() - tip).norm(), 1e-3 * model.length);
}

}  // namespace
}  // namespace cosserat
