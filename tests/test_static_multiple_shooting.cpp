// Static multiple shooting: the same discrete equilibrium as single shooting where that
// converges (cantilevers and columns), a taut column beyond single shooting against the
// tensioned-beam solution, and a long rod on a stiff Winkler foundation (βL ≈ 44, beyond single
// shooting) against Hetényi's beam on an elastic foundation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cosserat/analysis/column.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/tensioned_beam.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using testing::SteelRod;

// A steel cantilever clamped along +z under gravity along −x and an oblique tip force (tip
// deflection ~0.2 L): both solvers converge to the residual tolerance 1e-10 (dimensionless
// wrench), which moves the nodes by ~1e-10 L times the condition of this well-posed problem;
// 1e-8 L is the bound asserted.
TEST(StaticMultipleShooting, SameEquilibriumAsSingleShooting) {
  SteelRod rod;
  rod.length = 0.5;
  rod.r = 0.001;
  const RodModel model = RodModel::Uniform(rod.length, rod.section(), rod.material);
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);
  loads.tip_force = Vec3(-0.3, 0.1, 0);
  StaticShootingSolver single(model, 41);
  ASSERT_TRUE(single.Solve(lie::SE3{}, loads).converged());
  for (int pieces : {2, 5, 8}) {
    StaticMultipleShootingOptions opt;
    opt.pieces = pieces;
    StaticMultipleShootingSolver multiple(model, 41, opt);
    const StaticShootingSummary s = multiple.Solve(lie::SE3{}, loads);
    ASSERT_TRUE(s.converged()) << pieces << " pieces";
    double worst = 0;
    for (int i = 0; i < 41; ++i)
      worst =
          std::max(worst, (multiple.state().position_W[i] - single.state().position_W[i]).norm());
    std::printf("%d pieces: %d load levels, %d iterations, max node distance %.2e m\n", pieces,
                s.load_steps + 1, s.iterations, worst);
    EXPECT_LT(worst, 1e-8 * rod.length) << pieces << " pieces";
  }
}

// The column ends (a tip guided along the axis): the same equilibrium as ColumnSolver's single
// shot where that converges, kL = 5 under tension and a side load of 0.3 T with a moment at the
// tip (deflection ~0.04 L; both converge to 1e-10 in their residuals: 1e-8 L asserted, as
// above, for one piece: the same discrete equations). RK4 does not keep R orthonormal: the
// single shot's R drifts by |RᵀR − I| ≈ 2e-7 over the rod here, which the junctions' restarts
// (on SO(3)) remove, so with 4 pieces the axial positions differ by up to ~1e-7 L (measured
// 5e-8 L): 2e-7 L asserted. Along the capped load path: a single step to the full load (before
// the cap) landed 0.37–0.46 L away, on another branch.
TEST(StaticMultipleShooting, ColumnEndsGiveColumnSolversEquilibrium) {
  const SteelRod rod{0.5, 1e-3};
  const double T = 25 * rod.EI() / (rod.length * rod.length);
  StaticLoads loads;
  loads.distributed_force_W = Vec3(0.3 * T / rod.length, 0.1 * T / rod.length, 0);
  loads.tip_force = Vec3(0, 0, T);
  loads.tip_moment = Vec3(0.05, -0.02, 0.01) * rod.EI() / rod.length;
  for (ColumnEnds ends :
       {ColumnEnds::kPinnedPinned, ColumnEnds::kClampedClamped, ColumnEnds::kClampedPinned}) {
    ColumnSolver single(rod.model(), 41, ends);
    ASSERT_TRUE(single.SolveFromUnloaded(lie::SE3{}, loads).converged()) << ToString(ends);
    for (int pieces : {1, 4}) {
      StaticMultipleShootingOptions opt;
      opt.pieces = pieces;
      opt.base_pinned = ends == ColumnEnds::kPinnedPinned;
      opt.tip_guided = true;
      opt.tip_clamped = ends == ColumnEnds::kClampedClamped;
      StaticMultipleShootingSolver multiple(rod.model(), 41, opt);
      ASSERT_TRUE(multiple.Solve(lie::SE3{}, loads).converged()) << ToString(ends);
      double worst = 0;
      for (int i = 0; i < 41; ++i)
        worst = std::max(worst,
                         (multiple.state().position_W[i] - single.state().position_W[i]).norm());
      std::printf("%s, %d pieces: max node distance %.2e m\n", ToString(ends), pieces, worst);
      EXPECT_LT(worst, (pieces == 1 ? 1e-8 : 2e-7) * rod.length)
          << ToString(ends) << ", " << pieces << " pieces";
    }
  }
}

// A taut pinned-pinned column at kL = L sqrt(T/EI) = 40, where a single shot amplifies its
// errors by e^40 (ColumnSolver's Newton lands on a looped equilibrium there), under a side load
// for a string sag of 1e-4 L: EI y'''' − T y'' = q. The wire is thin (r/L = 1/2000) so that
// its stretch T/EA = (kL)² (r/2L)² = 1e-4 and shear stay below 1e-3 of the sag, the bound
// asserted; RK4 resolves the end boundary layers (k h = 1) to ~1e-5.
TEST(StaticMultipleShooting, ATautColumnBeyondSingleShootingSagsAsATensionedBeam) {
  const SteelRod rod{0.5, 0.25e-3};
  const double T = 1600 * rod.EI() / (rod.length * rod.length);
  const double q = 8 * T * 1e-4 / rod.length;  // N/m
  StaticLoads loads;
  loads.distributed_force_W = Vec3(q, 0, 0);
  loads.tip_force = Vec3(0, 0, T);
  ASSERT_GT(StaticShootingExponent(rod.model(), loads), 39.0);
  StaticMultipleShootingOptions opt;
  opt.base_pinned = opt.tip_guided = true;
  StaticMultipleShootingSolver solver(rod.model(), 41, opt);
  const StaticShootingSummary s = solver.Solve(lie::SE3{}, loads);
  ASSERT_TRUE(s.converged()) << ToString(s.status);
  EXPECT_GT(solver.pieces(), 1);
  const double expected = truth::TensionedBeamMidSpanDeflection(q, T, rod.EI(), rod.length);
  EXPECT_NEAR(solver.state().position_W[20].x() / expected, 1.0, 1e-3);
  // The guided tip sits on the axis, pulled out by the stretch T L / EA less the sag's
  // shortening (8/3) δ² / L (both ~1e-4 L; 1e-5 L bounds their second-order remainder and RK4).
  const Vec3 tip = solver.state().position_W.back();
  EXPECT_NEAR(tip.x(), 0.0, 1e-12);
  EXPECT_NEAR(tip.z(),
              rod.length * (1 + T / rod.EA()) - 8.0 / 3.0 * expected * expected / rod.length,
              1e-5 * rod.length);
}

// A 2.5 m steel rod (r 2 mm, EI = 2.51 N·m²) lies along x on a plane with a penalty k = 1e6 N/m
// per m (β = (k/4EI)^{1/4} = 17.8 /m, βL = 44), pressed into it by a uniform load q (gravity of
// 1000 m/s²) and clamped at the height where the far field is in equilibrium, with a downward
// force P = 1 N at its free end. Hetényi (1946): a semi-infinite beam on a Winkler foundation
// with an end load sinks at the end by 2Pβ/k and turns by 2Pβ²/k; the clamp is e^{−44} away.
// Departures: shear deformation (EI β² / κGA ≈ 1e-3), RK4 on 500 segments ((βh)⁴ ≈ 6e-5), the
// nonlinearity (slopes ~1e-3: ~1e-6), the contact smoothing ε = 1 nm (1e-5 of the sinking):
// 0.5 % bounds them together.
TEST(StaticMultipleShooting, ABeamOnAStiffFoundationSinksAsHetenyiPredicts) {
  SteelRod rod;
  rod.length = 2.5;
  rod.r = 0.002;
  const RodModel model = RodModel::Uniform(rod.length, rod.section(), rod.material);
  const double k = 1e6, eps = 1e-9, g = 1000.0, P = 1.0;
  const double q = rod.rhoA() * g, beta = std::pow(k / (4 * rod.EI()), 0.25);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -g);
  loads.tip_force = Vec3(0, 0, -P);
  loads.contact.count = 1;
  ContactSurface& plane = loads.contact.surface[0];
  plane.stiffness = k;
  plane.smoothing = eps;
  // k (δ − ε/2) = q balances the far field at the penetration δ.
  const double sink = q / k + 0.5 * eps;
  lie::SE3 base;
  base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // tangent along +x
  base.p = Vec3(0, 0, rod.r - sink);
  std::printf("beta L = %.1f, exponent for the pieces %.1f\n", beta * rod.length,
              StaticShootingExponent(model, loads));

  StaticShootingOptions single_options;
  single_options.max_load_steps = 20;
  single_options.stable_branch = false;
  StaticShootingSolver single(model, 501, single_options);
  EXPECT_FALSE(single.Solve(base, loads).converged())
      << "single shooting resolved beta L = 44: update this test's premise";

  StaticMultipleShootingSolver multiple(model, 501);
  const StaticShootingSummary s = multiple.Solve(base, loads);
  std::printf("%d pieces, %d load levels, %d iterations, %d piece shots, %.3f s\n",
              multiple.pieces(), s.load_steps + 1, s.iterations, s.shots, s.wall_time_s);
  ASSERT_TRUE(s.converged());
  EXPECT_GT(multiple.pieces(), 4);
  const RodState& st = multiple.state();
  const double deflection = base.p.z() - st.tip_position_W().z();
  const double slope = -st.rotation_WB.back().col(2).z();
  const double expected_deflection = 2 * P * beta / k, expected_slope = 2 * P * beta * beta / k;
  std::printf("end deflection %.6e m (Hetenyi %.6e), slope %.6e (Hetenyi %.6e)\n", deflection,
              expected_deflection, slope, expected_slope);
  EXPECT_NEAR(deflection, expected_deflection, 5e-3 * expected_deflection);
  EXPECT_NEAR(slope, expected_slope, 5e-3 * expected_slope);
  // The far half has not moved: the clamp is e^{-βL/2} ≈ 2e-10 away from any disturbance.
  EXPECT_NEAR(st.position_W[250].z(), base.p.z(), 1e-9);
}

TEST(StaticMultipleShooting, BadOptionsAreErrors) {
  const RodModel model = RodModel::Uniform(0.5, CrossSection::Circle(0.001), testing::Steel());
  StaticMultipleShootingOptions opt;
  opt.pieces = 11;
  EXPECT_THROW(StaticMultipleShootingSolver(model, 11, opt), std::invalid_argument);
  opt.pieces = -1;
  EXPECT_THROW(StaticMultipleShootingSolver(model, 11, opt), std::invalid_argument);
}

// A continuation that cannot reach the full load says so: a 2 mm wire 2³¹ m long under its own
// weight (its weight is 10¹⁹ times EI/L²) stops short, and the status is load_stepping_failed,
// not max_iterations at the last level it reached.
TEST(StaticMultipleShooting, AContinuationThatStopsShortIsLoadSteppingFailed) {
  const RodModel model =
      RodModel::Uniform(2147483648.0, CrossSection::Circle(0.001), testing::Steel());
  StaticMultipleShootingSolver solver(model, 41, StaticMultipleShootingOptions{});
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  lie::SE3 base;
  base.R = lie::SO3Exp(Vec3(0, 0.5 * M_PI, 0));  // horizontal
  const StaticShootingSummary s = solver.Solve(base, loads);
  EXPECT_EQ(s.status, SolveStatus::kLoadSteppingFailed) << ToString(s.status);
  EXPECT_GT(s.load_steps, 0);
}

}  // namespace
}  // namespace cosserat
