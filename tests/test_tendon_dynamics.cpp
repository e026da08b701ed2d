// Actuation in the BDF2 stepper: tendon tension steps settle on the static solution, and
// switching a jamming segment mid-run moves nothing discontinuously.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using testing::DampedSteel;

// For every spatial scheme: with Heun the stepper settles on Heun's discrete equilibrium, which
// differs from the static solver's RK4 one by Heun's spatial error, O((h κ)²) relative with
// h κ ≈ 0.005 here (measured 1.0e-6 m, RK4 2.8e-10 m), far inside the acceptance of 1e-4 L.
TEST(TendonDynamics, TensionStepWithDampingSettlesToTheStaticSolution) {
  const CrossSection sec = CrossSection::Circle(0.001);
  RodModel model = RodModel::Uniform(0.25, sec, DampedSteel(sec, 2e-3));
  model.tendons = {{"a", TendonRoute::Parallel(Vec2(0.004, 0))},
                   {"b", TendonRoute::Helical(0.003, 0.25, 0.0)}};
  for (SpatialScheme scheme :
       {SpatialScheme::kRk4, SpatialScheme::kHeun, SpatialScheme::kRk4Pairs}) {
    Bdf2Options opt;
    opt.dt = 2e-3;
    opt.spatial_scheme = scheme;
    Bdf2ShootingStepper stepper(model, 41, opt);
    StepInput in;
    in.loads.gravity_W = Vec3(0, -9.81, 0);
    ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
    in.actuation.tendon_tension[0] = 30.0;  // the step: κ = τr/EI ≈ 0.76 /m, tip moves ≈ 24 mm
    in.actuation.tendon_tension[1] = 1.0;
    // First mode ≈ 140 rad/s, modal damping ζ ≈ ω τ/2 ≈ 0.14: e^{-ζωt} < 1e-6 by t = 0.8 s.
    for (int i = 0; i < 400; ++i) ASSERT_TRUE(stepper.Step(in).converged()) << i;
    StaticShootingSolver statics(model, 41, {}, in.actuation);
    ASSERT_TRUE(statics.Solve(in.base_pose, in.loads).converged());
    const double moved = statics.state().tip_position_W().x();
    EXPECT_GT(moved, 0.02);  // the tension really bends the rod (towards the tendon, +x)
    const double gap = (stepper.state().tip_position_W() - statics.state().tip_position_W()).norm();
    std::printf("%s: settled tip vs static solver %.3g m\n",
                scheme == SpatialScheme::kRk4    ? "rk4"
                : scheme == SpatialScheme::kHeun ? "heun"
                                                 : "rk4-pairs",
                gap);
    // Acceptance: 1e-4 L. RK4: both solve the same discrete equations in s at rest.
    EXPECT_LT(gap, 1e-4 * model.length);
  }
}

/// robots/tendon_three_tendon.json, parsed (the file is the repository's: it must parse).
io::Problem ThreeTendonRobot() {
  const io::ParseResult parsed =
      io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/robots/tendon_three_tendon.json");
  if (!parsed.ok()) throw std::runtime_error(parsed.errors.front());
  return *parsed.problem;
}

// A controller's episode reset: InitializeAtRest starts a new run, and the same inputs must give
// the same run, bit for bit, whatever an earlier run did. The three-tendon robot under random
// tension jumps adds shooting pieces when a step fails (the stepper's own escalation); a reset
// that kept them shot the second run in other pieces and moved its tip by ~5e-7 m.
TEST(TendonDynamics, InitializeAtRestStartsTheSameRunAgain) {
  const io::Problem p = ThreeTendonRobot();
  Bdf2ShootingStepper stepper(p.rod, p.nodes, run::DynamicsOptions(p));
  std::mt19937 random(1);
  std::uniform_real_distribution<double> tension(0.0, 3.0);
  std::vector<Actuation> inputs(30);
  for (Actuation& a : inputs)
    for (int k = 0; k < 3; ++k) a.tendon_tension[k] = tension(random);
  StepInput in;
  in.loads = p.loads;
  std::vector<Vec3> runs[2];
  int most_pieces = 0;
  for (std::vector<Vec3>& tips : runs) {
    in.actuation = Actuation{};
    ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
    for (const Actuation& a : inputs) {
      in.actuation = a;
      const StepSummary s = stepper.Step(in);
      ASSERT_TRUE(s.converged());
      most_pieces = std::max(most_pieces, s.shooting_segments);
      tips.push_back(stepper.state().tip_position_W());
    }
  }
  // The first run escalated (else this test would not test the reset).
  ASSERT_GT(most_pieces, 1);
  for (size_t k = 0; k < runs[0].size(); ++k) EXPECT_EQ(runs[0][k], runs[1][k]) << "step " << k;
}

// The same where the run starts in pieces and keeps them: a nitinol backbone (0.25 m, r 0.6 mm,
// four tendons 6 mm out) at dt = 1 ms shoots in 3 pieces from its start. The junction states an
// earlier run left must not seed the next run's steps (they would move its tip by ~1e-14 m):
// the run after a reset is a new stepper's, bit for bit.
TEST(TendonDynamics, InitializeAtRestForgetsTheJunctionsOfTheLastRun) {
  RodModel rod = RodModel::Uniform(0.25, CrossSection::Circle(0.0006),
                                   Material::FromShearModulus(58e9, 21.8e9, 6450));
  for (int i = 0; i < 4; ++i)
    rod.tendons.push_back({"t" + std::to_string(i),
                           TendonRoute::Parallel(0.006 * Vec2(std::cos(i * M_PI / 2),
                                                              std::sin(i * M_PI / 2)))});
  Bdf2Options options;
  options.dt = 1e-3;
  Bdf2ShootingStepper used(rod, 41, options), fresh(rod, 41, options);
  StepInput in;
  in.loads.gravity_W = Vec3(0, 0, -9.81);
  auto pull = [&](int k) { in.actuation.tendon_tension[0] = 0.5 + 0.5 * std::sin(0.01 * k); };
  ASSERT_TRUE(used.InitializeAtRest(in).converged());
  for (int k = 0; k < 200; ++k) {
    pull(k);
    ASSERT_TRUE(used.Step(in).converged());
  }
  in.actuation = Actuation{};
  ASSERT_TRUE(used.InitializeAtRest(in).converged());
  ASSERT_TRUE(fresh.InitializeAtRest(in).converged());
  ASSERT_GT(fresh.ChosenPieces(), 1);  // else this would not test the junctions
  for (int k = 0; k < 50; ++k) {
    pull(k);
    ASSERT_TRUE(used.Step(in).converged());
    ASSERT_TRUE(fresh.Step(in).converged());
    ASSERT_EQ(used.state().tip_position_W(), fresh.state().tip_position_W()) << "step " << k;
  }
}

// The pieces a failed step adds are for the transient that failed: the three-tendon robot hit
// by 30 N on one tendon for one step (the rod curls through κL ≈ 14 rad: its steps fail until
// it shoots in 20 pieces), then held at its own tensions, goes back to the pieces chosen for
// it (a step in one piece costs 4–7× less than in 20 here), and a run restored half-way repeats the
// original bit for bit, drops included.
TEST(TendonDynamics, PiecesAddedForASpikeAreDroppedAfterWholeSteps) {
  const io::Problem p = ThreeTendonRobot();
  Bdf2ShootingStepper stepper(p.rod, p.nodes, run::DynamicsOptions(p));
  StepInput in;
  in.loads = p.loads;
  in.actuation = p.robot.actuation;
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  const int chosen = stepper.ChosenPieces();
  StepInput spike = in;
  spike.actuation.tendon_tension[0] = 30.0;
  ASSERT_TRUE(stepper.Step(spike).converged());
  const int after_spike = stepper.Step(in).shooting_segments;
  ASSERT_GT(after_spike, 2 * chosen);  // the spike escalated (else nothing here is tested)
  std::vector<Vec3> tips;
  std::optional<Bdf2ShootingStepper::Snapshot> half_way;
  int last = after_spike;
  for (int k = 0; k < 1000; ++k) {
    if (k == 150) half_way = stepper.Save();
    const StepSummary s = stepper.Step(in);
    ASSERT_TRUE(s.converged()) << k;
    last = s.shooting_segments;
    tips.push_back(stepper.state().tip_position_W());
  }
  EXPECT_EQ(last, stepper.ChosenPieces());
  stepper.Restore(*half_way);
  for (int k = 150; k < 1000; ++k) {
    ASSERT_TRUE(stepper.Step(in).converged()) << k;
    ASSERT_EQ(stepper.state().tip_position_W(), tips[k]) << k;
  }
}

// Largest node displacement over the step in which segment 0 unjams, for step size dt.
double SwitchJump(double dt) {
  const CrossSection sec = CrossSection::Circle(0.001);
  const Material steel = testing::Steel();
  auto tube = std::make_shared<UniformSection>(sec, steel);
  // Layers adding about the tube's own EI when jammed at ΔP = 100 kPa, 1 % of it unjammed.
  const double I_layer = 20 * sec.I1;
  std::vector<JammingSegment> segments = {{0.0, 0.125, I_layer, ModulusLaw::Affine(1e8, 1e5)},
                                          {0.125, 0.25, I_layer, ModulusLaw::Affine(1e8, 1e5)}};
  RodModel model;
  model.length = 0.25;
  model.section = std::make_shared<JammingSection>(tube, segments);
  model.tendons = {{"a", TendonRoute::Parallel(Vec2(0.004, 0))}};
  Bdf2Options opt;
  opt.dt = dt;
  Bdf2ShootingStepper stepper(model, 41, opt);
  StepInput in;
  in.actuation.jamming_pressure[0] = 1e5;
  in.actuation.tendon_tension[0] = 2.0;
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  const int before = static_cast<int>(std::lround(0.02 / dt));
  for (int i = 0; i < before; ++i) EXPECT_TRUE(stepper.Step(in).converged());
  const RodState prior = stepper.state();
  in.actuation.jamming_pressure[0] = 0.0;  // unjam segment 0: it now bends more
  EXPECT_TRUE(stepper.Step(in).converged());
  double jump = 0;
  for (int i = 0; i < prior.size(); ++i)
    jump = std::max(jump, (stepper.state().position_W[i] - prior.position_W[i]).norm());
  return jump;
}

TEST(TendonDynamics, SwitchingAJammingSegmentMidRunMovesNothingDiscontinuously) {
  // From rest in equilibrium, the switch changes the stiffness, not the state: the shape then
  // accelerates from rest. A jump in position would not shrink with dt (ratio 1 per halving);
  // continuous motion does, by 4× for the modes dt resolves (a dt²) and less for the stiff ones
  // that BDF2 relaxes within a step. Measured 2.47; asserted > 1.8.
  const double coarse = SwitchJump(2e-3), fine = SwitchJump(1e-3);
  EXPECT_GT(coarse, 0.0);
  EXPECT_LT(fine, coarse / 1.8) << "coarse " << coarse << " fine " << fine;
  EXPECT_LT(coarse, 1e-3 * 0.25);  // and it is small in absolute terms
}

TEST(TendonStatics, JammedAndCompliantCurvaturesFollowTheirStiffnessRatio) {
  // One straight tendon and no external load: the moment is τ r along the whole body (tension
  // is internal), so each segment bends with κ = τ r / EI_eff: the curvature ratio of a
  // compliant and a jammed segment is their stiffness ratio (acceptance: 0.5 %).
  const CrossSection sec = CrossSection::Annulus(0.01, 0.009);
  const Material tube_material = Material::FromPoissonRatio(1e6, 0.45, 1100);
  auto tube = std::make_shared<UniformSection>(sec, tube_material);
  const std::vector<JammingSegment> segments = {{0.0, 0.2, 2e-9, ModulusLaw::Affine(0, 1000)},
                                                {0.2, 0.4, 2e-9, ModulusLaw::Affine(0, 1000)},
                                                {0.4, 0.6, 2e-9, ModulusLaw::Affine(0, 1000)}};
  auto jamming = std::make_shared<JammingSection>(tube, segments);
  RodModel model;
  model.length = 0.6;
  model.section = jamming;
  model.tendons = {{"bend", TendonRoute::Parallel(Vec2(0.008, 0))}};
  Actuation a;
  a.tendon_tension[0] = 1.0;
  a.jamming_pressure = {80000, 0, 80000};
  StaticShootingSolver solver(model, 31, {}, a);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, StaticLoads{}).converged());
  const RodState& st = solver.state();
  const double compliant = st.strain[15].head<2>().norm();  // s = 0.3, middle segment
  const double jammed = st.strain[5].head<2>().norm();      // s = 0.1
  const double ratio = jamming->StiffnessRatio(0, 1, a);    // EI(jammed) / EI(compliant)
  EXPECT_GT(ratio, 10.0);
  EXPECT_NEAR(compliant / jammed / ratio, 1.0, 5e-3);
}

}  // namespace
}  // namespace cosserat
