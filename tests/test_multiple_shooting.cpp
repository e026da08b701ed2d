// Multiple shooting in the BDF2 stepper (Bdf2Options::shooting_segments): the same discrete
// solution as single shooting, and time steps below single shooting's conditioning limit, where
// the second-order convergence in dt continues.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <cstdio>
#include <vector>

#include "../bench/peer_rod.hpp"
#include "cosserat/lie/nearest_rotation.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/shooting_exponent.hpp"
#include "support/analytic/beam_vibration.hpp"
#include "support/rods.hpp"
#include "support/smooth_ramp.hpp"

namespace cosserat {
namespace {

using bench::PeerRod;  // steel, L = 0.5 m, r = 1 mm
using truth::kPi;
constexpr double kLength = 0.5, kRadius = 0.001;

// The peer problem's release (gravity along −x, a 0.02 kg tip weight removed at t = 0), `steps`
// steps of dt; the tip position after each.
std::vector<Vec3> Release(int nodes, double dt, int pieces, int steps, bool* ok,
                          SpatialScheme scheme = SpatialScheme::kRk4) {
  Bdf2Options opt;
  opt.dt = dt;
  opt.shooting_segments = pieces;
  opt.spatial_scheme = scheme;
  Bdf2ShootingStepper stepper(PeerRod(), nodes, opt);
  StepInput in = bench::PeerPreload();
  *ok = stepper.InitializeAtRest(in).converged();
  in.loads.tip_force.setZero();
  std::vector<Vec3> tip;
  for (int i = 0; i < steps && *ok; ++i) {
    *ok = stepper.Step(in).converged();
    tip.push_back(stepper.state().tip_position_W());
  }
  return tip;
}

TEST(MultipleShooting, SameSolutionAsSingleShooting) {
  // dt = 2 ms, where single shooting works: both solve the same discrete equations, each step to
  // a dimensionless residual of 1e-10 (moments in EI/L, forces in EI/L²), so the tips may differ
  // by about that much in units of L, times the step's sensitivity, compounded over the steps;
  // 1e-8 L leaves a factor 7 (measured: 1.5e-9 L).
  // With Heun in s the two differ more, and not by the solver: explicit integration of R' = R K̂
  // leaves SO(3) by the scheme's truncation error (max |RᵀR − I| along this rod: 2e-9 with RK4,
  // 1e-6 with Heun), and each junction restarts on SO(3) (R Exp(δθ)), which single shooting
  // never does. So the discrete equations differ by that drift: bound 2e-6 L (measured
  // 2.5e-7 L), still far below Heun's own spatial error here (3.6e-4 L over the first 0.2 s,
  // test_spatial_scheme.cpp).
  // RK4 across pairs (the default; 19 pairs at 40 nodes): the junctions sit between pairs, so
  // the discrete equations are again those of single shooting but for RK4's SO(3) drift at
  // twice the step, 2⁴ = 16 times RK4's: bound 2e-7 L (measured 2.2e-8 L, 15 times RK4's).
  for (SpatialScheme scheme :
       {SpatialScheme::kRk4, SpatialScheme::kHeun, SpatialScheme::kRk4Pairs}) {
    bool ok_single = false, ok_multiple = false;
    const auto single = Release(40, 2e-3, 1, 200, &ok_single, scheme);
    const auto multiple = Release(40, 2e-3, 4, 200, &ok_multiple, scheme);
    ASSERT_TRUE(ok_single && ok_multiple);
    double worst = 0;
    for (size_t i = 0; i < single.size(); ++i)
      worst = std::max(worst, (single[i] - multiple[i]).norm());
    std::printf("%s: single vs 4 pieces over 200 steps: max tip difference %.3g L\n",
                scheme == SpatialScheme::kRk4    ? "rk4"
                : scheme == SpatialScheme::kHeun ? "heun"
                                                 : "rk4-pairs",
                worst / kLength);
    EXPECT_LT(worst / kLength, scheme == SpatialScheme::kRk4    ? 1e-8
                               : scheme == SpatialScheme::kHeun ? 2e-6
                                                                : 2e-7);
  }
}

// A steel wire (L = 1 m, r = 1 mm) clamped at the origin along +z, pulled at its tip by 3.9 N
// along z and 0.05 N across (L √(T/EI) = 5), then pinned where that left it and solved at rest
// in four pieces from the single shot's equilibrium. The junctions restart from the frames of
// the state they are taken from; frames off SO(3) by 1e-7 (what explicit RK stages leave in a
// stiffer rod's tension boundary layer) stretched each piece by that much, which the junctions'
// rotation mismatch, the skew part of Log, cannot see: the tension moved by 0.035 N (9e-3).
// The restarts are on SO(3) now, so both starts must give one solution: a held tip fixes the
// tension only to EA times the solve's tolerance on its position (1e-10 L: 6e-5 N; measured
// 2.5e-7 N apart). Against the single shot, which carries RK4's drift δ of the frames (here
// 9e-10) through the junctions instead, the tension differs by up to EA δ more (measured
// 1.5e-4 N).
TEST(MultipleShooting, TheRestSolutionDoesNotDependOnTheFramesItStartsFrom) {
  const testing::SteelRod wire{1.0, 0.001};
  auto tension = [](const RodState& s) { return s.wrench_B.front()(5); };
  Bdf2ShootingStepper pulled(wire.model(), 41);
  StepInput in;
  in.loads.tip_force = Vec3(0.05, 0, 3.9);
  ASSERT_TRUE(pulled.InitializeAtRest(in).converged());
  const RodState exact = pulled.state();
  double drift = 0;
  for (const Mat3& R : exact.rotation_WB) drift = std::max(drift, lie::OrthonormalityError(R));
  RodState stretched = exact;
  for (Mat3& R : stretched.rotation_WB) R *= 1 + 1e-7;
  StepInput held;
  held.tip_hold = TipHold::kPinned;
  held.tip_pose.p = exact.tip_position_W();
  Bdf2Options opt;
  opt.shooting_segments = 4;
  const double noise = wire.EA() * opt.tolerance;  // N
  double T[2];
  for (int k = 0; k < 2; ++k) {
    Bdf2ShootingStepper pieces(wire.model(), 41, opt);
    ASSERT_TRUE(pieces.InitializeAtRest(held, k == 0 ? exact : stretched).converged());
    T[k] = tension(pieces.state());
    std::printf("at rest in 4 pieces from %s frames: tension %.12f N (single shot %.12f N, "
                "its frames' drift %.2e)\n",
                k == 0 ? "the RK" : "stretched", T[k], tension(exact), drift);
    EXPECT_NEAR(T[k], tension(exact), wire.EA() * drift + noise);
  }
  EXPECT_NEAR(T[0], T[1], noise);
}

// A free rod at rest in free space, released into uniform gravity at t = 0: it translates
// rigidly, x = g t²/2 exactly. With the backward Euler first step the velocity is exact from the
// first step on and the position error is the first step's g dt²/2, which BDF2's recursion
// 3e_n − 4e_{n−1} + e_{n−2} = 0 carries to the constant 3/2 × g dt²/2 = 0.75 g dt² (second
// order). BDF2 over the rest history keeps M = (3 v_n − v_{n−1})/2 = n g dt, so the velocity
// lags by g dt/2 and the position by g dt t/2 (first order). Asserted within 2 %: the
// backward Euler value is exact (solver tolerance and round-off are ~1e-10 of it), the lag has
// start-up terms of relative size ~dt/T (1.5 % measured at dt = 1 ms).
TEST(Bdf2Start, AReleaseIntoGravityIsSecondOrderWithABackwardEulerFirstStep) {
  auto drop_error = [](Bdf2Options::FirstStep first, double dt, double t_end) {
    Bdf2Options opt;
    opt.ends = EndConditions::kFreeFree;
    opt.dt = dt;
    opt.first_step = first;
    Bdf2ShootingStepper stepper(PeerRod(), 21, opt);
    StepInput in;
    EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
    const Vec3 start = stepper.CentreOfMass_W();
    in.loads.gravity_W = Vec3(-9.81, 0, 0);
    const int steps = static_cast<int>(std::lround(t_end / dt));
    for (int i = 0; i < steps; ++i) EXPECT_TRUE(stepper.Step(in).converged());
    const double fallen = start.x() - stepper.CentreOfMass_W().x();
    return fallen - 0.5 * 9.81 * t_end * t_end;  // > 0: fell too far
  };
  const double g = 9.81, T = 0.1;
  for (double dt : {1e-3, 5e-4}) {
    const double be = drop_error(Bdf2Options::FirstStep::kBackwardEuler, dt, T);
    const double bdf2 = drop_error(Bdf2Options::FirstStep::kBdf2OverRest, dt, T);
    std::printf(
        "dt %g s: position error %.4g m (backward Euler start; 0.75 g dt^2 = %.4g), "
        "%.4g m (BDF2 over the rest; -g dt T/2 = %.4g)\n",
        dt, be, 0.75 * g * dt * dt, bdf2, -0.5 * g * dt * T);
    EXPECT_NEAR(be, 0.75 * g * dt * dt, 0.02 * 0.75 * g * dt * dt);
    EXPECT_NEAR(bdf2, -0.5 * g * dt * T, 0.02 * 0.5 * g * dt * T);
  }
}

TEST(MultipleShooting, BadPieceCountIsAnError) {
  Bdf2Options opt;
  opt.shooting_segments = -1;  // 0 is automatic
  EXPECT_THROW(Bdf2ShootingStepper(PeerRod(), 11, opt), std::invalid_argument);
  opt.shooting_segments = 11;  // 11 nodes have 10 segments
  EXPECT_THROW(Bdf2ShootingStepper(PeerRod(), 11, opt), std::invalid_argument);
}

// Second order in dt down to steps single shooting cannot take. The setup of
// Bdf2Dynamics.SecondOrderInTime (a tip load ramped in with three continuous derivatives over
// one period, tip sampled 32 times over two periods) on the peer rod, with dt = 2T/(32 m) for
// m = 16, 32, 64: 0.70, 0.35 and 0.17 ms. Single shooting's exponent λL ≈ 17 sqrt(0.5 ms / dt)
// reaches 29 at the finest step (e^29 ≈ 4e12: the residual cannot get below 1e-10 in double
// precision); 8 pieces see e^3.6 each.
TEST(MultipleShooting, SecondOrderInTimeBelowTheSingleShootingLimit) {
  const testing::SteelRod rod{kLength, kRadius};
  const double EI = rod.EI();
  const double w1 = truth::EulerBernoulliOmega(truth::CantileverBetaL(1), EI, rod.rhoA(), kLength);
  const double period = 2 * kPi / w1;
  const double P = 1e-2 * 3 * EI / (kLength * kLength);
  const int samples = 32;
  auto trajectory = [&](int steps_per_sample, int pieces, bool* ok) {
    Bdf2Options opt;
    opt.dt = 2 * period / (samples * steps_per_sample);
    opt.shooting_segments = pieces;
    opt.max_halvings = 0;
    // RK4 in s errs like (λh)⁵ per segment and λ grows like dt^(-1/2): 161 nodes keep
    // λh ≈ 0.18 at the finest step, so the spatial error does not hide the temporal order.
    Bdf2ShootingStepper stepper(PeerRod(), 161, opt);
    StepInput in;
    *ok = stepper.InitializeAtRest(in).converged();
    std::vector<Vec3> out;
    for (int i = 1; i <= samples * steps_per_sample && *ok; ++i) {
      const double u = std::min(1.0, i * opt.dt / period);
      const double ramp = testing::SmoothRamp(u);
      in.loads.tip_force = Vec3(-P * ramp, 0, 0);
      *ok = stepper.Step(in).converged();
      if (i % steps_per_sample == 0) out.push_back(stepper.state().tip_position_W());
    }
    return out;
  };
  bool ok = false;
  // Single shooting at the finest step: the status says it failed (no wrong answer).
  trajectory(64, 1, &ok);
  EXPECT_FALSE(ok) << "single shooting converged at dt = 0.17 ms: update this test's premise";
  bool ok_a = false, ok_b = false, ok_c = false;
  const auto a = trajectory(16, 8, &ok_a), b = trajectory(32, 8, &ok_b),
             c = trajectory(64, 8, &ok_c);
  ASSERT_TRUE(ok_a && ok_b && ok_c);
  double e1 = 0, e2 = 0;
  for (int k = 0; k < samples; ++k) {
    e1 = std::max(e1, (a[k] - b[k]).norm());
    e2 = std::max(e2, (b[k] - c[k]).norm());
  }
  std::printf("dt 0.70 -> 0.35 ms: %.3g m, 0.35 -> 0.17 ms: %.3g m, order %.3f\n", e1, e2,
              std::log2(e1 / e2));
  // Order 2: a ratio of 4 (ω1 dt ≤ 0.025, deep in the asymptotic range; the same bound as
  // SecondOrderInTime's finer pair).
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.15);
}

// Free-free (FD notes 2025, eq. 29): the unknown at s = 0 is the twist; junctions work the same.
// A steel rod hit by an oblique tip impulse: the same motion as single shooting (measured 3e-12 m
// over 200 steps; bound argued as in SameSolutionAsSingleShooting).
TEST(MultipleShooting, FreeFreeSameSolutionAsSingleShooting) {
  std::vector<Vec3> tips[2];
  for (int pieces : {1, 4}) {
    Bdf2Options opt;
    opt.ends = EndConditions::kFreeFree;
    opt.dt = 1e-3;
    opt.shooting_segments = pieces;
    Bdf2ShootingStepper stepper(PeerRod(), 41, opt);
    StepInput in;
    ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
    for (int i = 0; i < 200; ++i) {
      in.loads.tip_force = i == 0 ? Vec3(0.01, 0.02, 0.005) : Vec3::Zero();
      ASSERT_TRUE(stepper.Step(in).converged()) << pieces << " pieces, step " << i;
      tips[pieces > 1].push_back(stepper.state().tip_position_W());
    }
  }
  double worst = 0;
  for (size_t i = 0; i < tips[0].size(); ++i)
    worst = std::max(worst, (tips[0][i] - tips[1][i]).norm());
  EXPECT_LT(worst / kLength, 1e-8);
}

// A soft, light free rod (E = 2 GPa, r = 2 mm, ρ = 1000 kg/m³) pushed sideways at its tip for 20
// steps of 1 ms: single shooting's exponent λL = (c0² ρA / EI)^{1/4} L ≈ 16 is past its limit and
// steps fail (a status, measured: from step 9 on); in 4 pieces every step converges, and the
// linear momentum afterwards is the applied impulse, 20 × 0.05 N × 1 ms — conserved to the
// solver tolerance (Bdf2FreeFree.LinearMomentumConservedToSolverTolerance: ~1e-8 relative over
// 1000 steps), so 1e-6 relative.
TEST(MultipleShooting, SoftFreeRodThatSingleShootingCannotResolve) {
  const RodModel soft = RodModel::Uniform(0.5, CrossSection::Circle(0.002),
                                          Material::FromShearModulus(2e9, 0.8e9, 1000));
  auto run = [&](int pieces, int* failed) {
    Bdf2Options opt;
    opt.ends = EndConditions::kFreeFree;
    opt.dt = 1e-3;
    opt.shooting_segments = pieces;
    Bdf2ShootingStepper stepper(soft, 41, opt);
    StepInput in;
    EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
    *failed = 0;
    for (int i = 0; i < 60; ++i) {
      // Pushed in steps 2 to 21 (the first, backward Euler, step stays at rest).
      in.loads.tip_force = i >= 1 && i <= 20 ? Vec3(0.05, 0, 0) : Vec3::Zero();
      if (!stepper.Step(in).converged()) ++*failed;
    }
    return stepper.Momentum().linear_W;
  };
  int failed_single = 0, failed_pieces = 0;
  run(1, &failed_single);
  const Vec3 momentum = run(4, &failed_pieces);
  EXPECT_GT(failed_single, 0) << "single shooting resolved λL ≈ 16: update this test's premise";
  EXPECT_EQ(failed_pieces, 0);
  const Vec3 impulse(20 * 0.05 * 1e-3, 0, 0);
  EXPECT_LT((momentum - impulse).norm(), 1e-6 * impulse.norm());
}

}  // namespace
}  // namespace cosserat

namespace cosserat {
namespace {

// A silicone cantilever (L 0.3 m, r 5 mm, E 1 MPa unless given, ν 0.5, ρ 1100 kg/m³, 51 nodes)
// clamped horizontally and released straight under gravity, 2 s undamped, with default options
// (automatic pieces). Returns what the run did; ok: every step converged.
struct SoftRun {
  bool ok = false;
  int pieces = 0;      // the pieces the run ended with
  int steps = 0;       // steps taken
  int iterations = 0;  // Newton iterations over the run
  Vec3 tip;
};

SoftRun SoftCantileverRelease(double dt, double youngs_modulus = 1e6) {
  const Material silicone = Material::FromPoissonRatio(youngs_modulus, 0.5, 1100);
  const RodModel rod = RodModel::Uniform(0.3, CrossSection::Circle(0.005), silicone);
  Bdf2Options opt;
  opt.dt = dt;
  Bdf2ShootingStepper stepper(rod, 51, opt);
  StepInput in;
  in.base_pose.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // tangent along +x
  SoftRun run;
  run.ok = stepper.InitializeAtRest(in).converged();
  in.loads.gravity_W = Vec3(0, 0, -9.81);
  const int steps = static_cast<int>(std::lround(2.0 / dt));
  for (int i = 0; i < steps && run.ok; ++i) {
    const StepSummary s = stepper.Step(in);
    run.ok = s.converged();
    run.pieces = s.shooting_segments;
    run.iterations += s.iterations;
    ++run.steps;
  }
  run.tip = stepper.state().tip_position_W();
  return run;
}

// The rod has swung down and back past the clamp's vertical: a rod that stayed put, or fell
// through its clamp, would not be here. |tip| is at most the stretched length: the rod's own
// weight stretches it by at most ρ g L / E (all of it hanging from the clamp), and a suddenly
// applied load at most doubles a static strain, so |tip| ≤ L (1 + 2 ρ g L / E).
void ExpectSwungDown(const SoftRun& run, double youngs_modulus) {
  EXPECT_LT(run.tip.z(), -0.15);
  EXPECT_LE(run.tip.norm(), 0.3 * (1 + 2 * 1100 * 9.81 * 0.3 / youngs_modulus));
}

// Single shooting fails at the first step here (λL = 19 … 42).
TEST(AutomaticPieces, ASoftCantileverRunsWithDefaultSettings) {
  for (double dt : {5e-3, 2e-3, 1e-3}) {
    const SoftRun run = SoftCantileverRelease(dt);
    std::printf("soft cantilever, dt = %g s: %s, %d pieces, %.2f iterations per step\n", dt,
                run.ok ? "converged" : "FAILED", run.pieces, double(run.iterations) / run.steps);
    EXPECT_TRUE(run.ok) << "dt = " << dt;
    EXPECT_GT(run.pieces, 1) << "single shooting cannot take these steps";
    ExpectSwungDown(run, 1e6);
    // Newton on the block-banded Jacobian: ~8 iterations per step measured (chord iterations
    // between renewals). A wrong block (a sign, a transpose, a missing rotation term of size
    // O(1)) makes the directions useless and the count explode or the step fail; 15 leaves room
    // for other machines' round-off.
    EXPECT_LT(run.iterations, 15 * run.steps) << "dt = " << dt;
  }
}

// Ten times softer (λL of about 34 and 53 at dt = 5 and 2 ms): the gain per piece is bounded by
// more pieces. (At dt = 1 ms, h λ ≈ 1.5 on 51 nodes: the grid, not the shooting, limits it; see
// docs/dynamics.md, "Grid and step".)
TEST(AutomaticPieces, ATenTimesSofterCantileverRunsWithDefaultSettings) {
  for (double dt : {5e-3, 2e-3}) {
    const SoftRun run = SoftCantileverRelease(dt, 1e5);
    std::printf("E = 100 kPa, dt = %g s: %s, %d pieces\n", dt, run.ok ? "converged" : "FAILED",
                run.pieces);
    EXPECT_TRUE(run.ok) << "dt = " << dt;
    ExpectSwungDown(run, 1e5);
  }
}

// The peer rod's section with every stiffness times actuation.stiffness_scale (as a jamming
// or pressure profile scales it).
class ScaledSteelSection final : public SectionProfile {
 public:
  SectionProperties At(double, const Actuation& a) const override {
    return UniformSectionProperties(
        CrossSection::Circle(0.001),
        Material::FromShearModulus(200e9 * a.stiffness_scale, 80e9 * a.stiffness_scale, 8000));
  }
  bool IsValid(double, std::string*) const override { return true; }
};

// A section that softens with the actuation, over 20 steps to 3 % of its stiffness (λL from
// 8.7 to about 20.9 at dt = 2 ms), re-chooses the pieces as the actuation changes, without a
// failed step: at the end λL/5 → 5 pieces. Growth after failed steps would double 1 → 2 → 4 → 8
// and never give 5.
TEST(AutomaticPieces, ASofteningActuationRechoosesThePieces) {
  RodModel rod = PeerRod();
  rod.section = std::make_shared<ScaledSteelSection>();
  Bdf2Options opt;
  opt.dt = 2e-3;
  Bdf2ShootingStepper stepper(rod, 40, opt);
  StepInput in = bench::PeerPreload();
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  StepSummary s;
  for (int i = 1; i <= 20; ++i) {
    in.actuation.stiffness_scale = std::pow(0.03, i / 20.0);
    s = stepper.Step(in);
    ASSERT_TRUE(s.converged()) << "step " << i;
    EXPECT_EQ(s.halvings, 0) << "step " << i;
  }
  const double exponent = SingleShootingExponent(rod, opt.dt, in.actuation);
  std::printf("softened: lambda L = %.1f, %d pieces\n", exponent, s.shooting_segments);
  EXPECT_EQ(s.shooting_segments, SuggestedShootingSegments(exponent));
  EXPECT_EQ(s.shooting_segments, 5);
}

// The steel peer rod (40 nodes, dt = 2 ms, automatic pieces) at rest under the peers' preload,
// then released: *in is the input without the preload's tip force.
std::unique_ptr<Bdf2ShootingStepper> ReleasedPeerRod(StepInput* in) {
  Bdf2Options opt;
  opt.dt = 2e-3;
  auto stepper = std::make_unique<Bdf2ShootingStepper>(PeerRod(), 40, opt);
  *in = bench::PeerPreload();
  EXPECT_TRUE(stepper->InitializeAtRest(*in).converged());
  in->loads.tip_force.setZero();
  return stepper;
}

TEST(AutomaticPieces, TheSteelPeerRodKeepsOneShot) {
  // λL ≈ 8.7 at dt = 2 ms: inside single shooting's safe range, so the real-time path keeps its
  // one shot per Newton iteration.
  StepInput in;
  const std::unique_ptr<Bdf2ShootingStepper> released = ReleasedPeerRod(&in);
  Bdf2ShootingStepper& stepper = *released;
  for (int i = 0; i < 50; ++i) {
    const StepSummary s = stepper.Step(in);
    ASSERT_TRUE(s.converged());
    EXPECT_EQ(s.shooting_segments, 1);
  }
}

// A one-tick spike of the input (a tip force of 2e4 N on the steel peer rod, ~80 times what
// bends it by its length) makes the stepper add pieces trying to converge (that step still
// fails, a status; the state stays the last converged one). Once the input is back, the
// pieces are halved back to the automatic choice after every kFirstDropWait steps taken whole,
// so the dear steps after a spike number about kFirstDropWait · log2(pieces), not hundreds.
TEST(AutomaticPieces, PiecesASpikeAddedAreDroppedSoonAfter) {
  StepInput in;
  const std::unique_ptr<Bdf2ShootingStepper> released = ReleasedPeerRod(&in);
  Bdf2ShootingStepper& stepper = *released;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(stepper.Step(in).converged());
  StepInput spike = in;
  spike.loads.tip_force = Vec3(2e4, 0, 0);
  const StepSummary hit = stepper.Step(spike);  // converged or not, it added pieces
  std::printf("spike: %s, %d pieces\n", ToString(hit.status), hit.shooting_segments);
  ASSERT_GT(hit.shooting_segments, 1);
  const int halvings = static_cast<int>(std::ceil(std::log2(hit.shooting_segments)));
  int back = -1;
  for (int i = 0; i < 400 && back < 0; ++i) {
    const StepSummary s = stepper.Step(in);
    ASSERT_TRUE(s.converged()) << i;
    if (s.shooting_segments == 1) back = i + 1;
  }
  std::printf("one piece again after %d steps\n", back);
  ASSERT_GT(back, 0);
  // Each halving waits kFirstDropWait whole steps; a few steps of the transient may still fail
  // and add pieces (each failure doubles the wait before the next drop): allow twice the wait.
  EXPECT_LE(back, 2 * Bdf2ShootingStepper::kFirstDropWait * halvings);
  // A second spike long after the first recovers as fast: the drop to one piece held, so the
  // wait is back to kFirstDropWait, not doubled as if that drop had failed.
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(stepper.Step(in).converged()) << i;
  const StepSummary again = stepper.Step(spike);
  int back_again = -1;
  for (int i = 0; i < 400 && back_again < 0; ++i) {
    const StepSummary s = stepper.Step(in);
    ASSERT_TRUE(s.converged()) << i;
    if (s.shooting_segments == 1) back_again = i + 1;
  }
  std::printf("after a second spike (%d pieces): one piece again after %d steps\n",
              again.shooting_segments, back_again);
  EXPECT_EQ(back_again, back);
}

}  // namespace
}  // namespace cosserat
