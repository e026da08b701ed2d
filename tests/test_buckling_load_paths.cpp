// Buckling along load paths other than a tip force, against analytic truths: tendon tension
// (never buckles a rod, whatever the route, while the same force as a dead tip load does at
// Euler's load) and inflation pressure (the lowest pressure at which an inflated column carries a
// given axial load: Euler's load with EI = E_eff(p) I solved for p).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cosserat/analysis/buckling.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "support/analytic/euler_buckling.hpp"
#include "support/analytic/tendon.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

// The steel column of test_buckling.cpp (r/L = 1/200), with one tendon.
RodModel SteelRodWithTendon(const TendonRoute& route) {
  RodModel model = testing::SteelRod{1.0, 0.005}.model();
  model.tendons.push_back(Tendon{"t0", route});
  return model;
}

// Tendon tension alone never buckles the rod. With no external load the internal wrench (rod +
// tendon, which Rucker & Webster's model sums into W) is zero all along, W ≡ 0, and so is every
// Jacobi field's δW (a linear ODE from δW(L) = 0). The strain then follows from
// H δξ = δW = 0 with H = K + τ ∇²|q|(ξ): the tendon's contribution a = ∇_ξ|q| (q = Γ + K × r + r')
// is the gradient of a norm of an affine function of ξ, so ∇²|q| is positive semidefinite and H
// is positive definite for every τ ≥ 0 and every route. So δξ ≡ 0: no conjugate point, J never
// singular, at any tension — for the centreline tendon and for an offset one alike. The same
// compressive force as a dead tip load buckles the rod at π²EI/(4L²) (test_buckling.cpp).
TEST(BucklingLoadPaths, TendonTensionNeverBucklesTheRod) {
  const double EI = testing::SteelRod{1.0, 0.005}.EI(), L = 1.0;
  const double P_euler = truth::EulerLoadClampedFree(EI, L);
  for (const TendonRoute& route :
       {TendonRoute::Parallel(Vec2::Zero()), TendonRoute::Parallel(Vec2(0.004, 0))}) {
    const RodModel model = SteelRodWithTendon(route);
    LoadPath path;
    path.tension_per_unit[0] = 1.0;  // λ = the tension, N
    BucklingOptions options;
    options.lambda_max = 10 * P_euler;  // ten Euler loads (2 400 N: axial strain 1.5e-4)
    BucklingAnalysis tendon(model, 41, ColumnEnds::kClampedFree, lie::SE3{}, path, options);
    const BucklingSummary b = tendon.FindCriticalLoad();
    EXPECT_EQ(b.status, BucklingStatus::kNotFound) << route.offset_base.transpose();
    EXPECT_DOUBLE_EQ(b.lambda_reached, options.lambda_max);
    // The offset tendon bends the rod into (nearly) a circle of curvature τ d / EI (a tip moment
    // τ d; the compression τ changes it by a factor 1 + O(τ/EA) = 1 + 1.5e-4).
    if (route.offset_base.x() > 0) {
      const double kappa = tendon.state().strain[20].head<2>().norm();
      EXPECT_NEAR(kappa, truth::TendonArcCurvature(options.lambda_max, 0.004, EI), 1e-3 * kappa);
    }
    std::printf("tendon offset %.3f m: %s up to %.0f N = %.0f Euler loads (%d solves)\n",
                route.offset_base.x(), ToString(b.status), b.lambda_reached,
                b.lambda_reached / P_euler, b.solves);

    // The plain static solve under that tension is stable (its stability check: index 0).
    Actuation act;
    act.tendon_tension[0] = options.lambda_max;
    StaticShootingSolver statics(model, 41, {}, act);
    const StaticShootingSummary st = statics.Solve(lie::SE3{}, StaticLoads{});
    ASSERT_TRUE(st.converged());
    EXPECT_EQ(st.stability_index, 0);

    // The same force, dead at the tip of the same rod (tendon slack): Euler's load, to the model
    // difference of test_buckling.cpp (−2.8e-5) well inside 0.5 %.
    LoadPath dead = LoadPath::TipForce(Vec3(0, 0, -1));
    options.lambda_max = 1.5 * P_euler;
    BucklingAnalysis tip(model, 41, ColumnEnds::kClampedFree, lie::SE3{}, dead, options);
    const BucklingSummary d = tip.FindCriticalLoad();
    ASSERT_TRUE(d.found());
    EXPECT_NEAR(d.critical_load / P_euler, 1.0, 5e-3);
  }
}

// An inflated beam (Suulker et al. 2026: EI = E_eff(p) I, E_eff affine in p) carrying a dead axial
// load P as a cantilever stands while π² E_eff(p) I/(4L²) > P: the lowest pressure is
// p_cr = (4 P L²/(π² I) − E0)/k. Found by following a pressure drop from 40 kPa.
// Model difference: shear and extension lower the rod's critical load by
// ε ≈ P/(κGA) − P/(EA) (test_buckling.cpp), so E_eff(p_cr) is higher by (1 + ε) and
// p_cr by ε E_eff/k: here ε = 5.5e-4 and the shift 5.8e-4 p_cr. Asserted < 2e-3.
TEST(BucklingLoadPaths, LowestInflationPressureIsEulersWithEffectiveModulus) {
  const double L = 1.25, r = 0.0125, t = 75e-6, E0 = 10e6, k = 1e4;  // E_eff = E0 + k p, Pa
  const CrossSection tube = CrossSection::Annulus(r, r - t);
  RodModel model = RodModel::Uniform(L, tube, Material::FromPoissonRatio(100e6, 0.45, 920));
  model.section = std::make_shared<PressureModulusSection>(
      tube, Material::FromPoissonRatio(100e6, 0.45, 920), ModulusLaw::Affine(E0, k));
  const double p_expected = 20e3;
  const double P = truth::EulerLoadClampedFree((E0 + k * p_expected) * tube.I1, L);
  StaticLoads loads;
  loads.tip_force = Vec3(0, 0, -P);
  const double p0 = 40e3;
  BucklingOptions options;
  options.lambda_max = p0;  // down to zero pressure
  BucklingAnalysis drop(model, 41, ColumnEnds::kClampedFree, lie::SE3{},
                        LoadPath::PressureDrop(p0, loads), options);
  const BucklingSummary b = drop.FindCriticalLoad();
  ASSERT_TRUE(b.found()) << ToString(b.status);
  const double p_cr = p0 - b.critical_load;
  std::printf("inflated cantilever under %.4f N: p_cr = %.2f Pa (Euler with E_eff: %.2f Pa, %+.2e)\n",
              P, p_cr, p_expected, p_cr / p_expected - 1);
  EXPECT_NEAR(p_cr / p_expected, 1.0, 2e-3);
  EXPECT_GT(p_cr, p_expected);  // shear softens: it takes a little more pressure

  // The two load paths meet: at p_cr the critical tip force is P (both are the same singular
  // point of J, each refined to 1e-11 relative).
  LoadPath force = LoadPath::TipForce(Vec3(0, 0, -1));
  force.fixed_actuation.pressure = p_cr;
  options.lambda_max = 2 * P;
  BucklingAnalysis at_p(model, 41, ColumnEnds::kClampedFree, lie::SE3{}, force, options);
  const BucklingSummary f = at_p.FindCriticalLoad();
  ASSERT_TRUE(f.found());
  EXPECT_NEAR(f.critical_load / P, 1.0, 1e-8);

  // A pressure path that would go below zero is refused, naming the field.
  options.lambda_max = 2 * p0;
  try {
    BucklingAnalysis bad(model, 41, ColumnEnds::kClampedFree, lie::SE3{},
                         LoadPath::PressureDrop(p0, loads), options);
    ADD_FAILURE() << "accepted a negative pressure";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lambda_max"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosserat
