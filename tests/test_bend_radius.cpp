// Minimum bend radius of an eversion robot against the closed form: under a growing pure tip
// moment the body first kinks where M reaches the wrinkling moment M_w(s) = π p r(s)³/2, and its
// radius there is EI(s)/M_w(s). With bands (EI = α E_eff I(s), I and M_w both ∝ r³)
// that is α times the plain tube's: bands give the tighter bend, as in the experiments.
#include <gtest/gtest.h>

#include <cmath>

#include "cosserat/analysis/bend_radius.hpp"
#include "support/analytic/inflated_beam.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

EversionRobotDesign Vine(std::vector<EversionBand> bands) {
  EversionRobotDesign d;
  d.radius = 0.025;
  d.wall_thickness = 75e-6;
  d.wall_modulus = ModulusLaw::Affine(100e6, 1e4);
  d.max_length = 1.0;
  d.bands = std::move(bands);
  return d;
}

TEST(BendRadius, BandsGiveAlphaTimesThePlainRadiusAtTheKink) {
  const double p = 3e3, L = 1.0, r = 0.025;
  const double EI = (100e6 + 1e4 * p) * kPi * r * r * r * 75e-6;
  const double M_w = truth::WrinklingMoment(p, r);
  StaticLoads moment;
  moment.tip_moment = Vec3(0, 2 * M_w, 0);  // the actuation range: up to twice the kink moment

  EversionRobot plain(Vine({}), L, p);
  const BendRadiusResult a = MinimumBendRadius(plain, StaticLoads{}, moment);
  ASSERT_EQ(a.limit, "kink");
  // Uniform moment: the kink is reached at λ = 1/2 and the radius is EI/M_w everywhere. Bisection
  // to 1e-6 in λ; the closed-vessel stretch changes κ by ≪ 1e-6.
  EXPECT_NEAR(a.load_factor, 0.5, 1e-5);
  EXPECT_NEAR(a.min_radius / (EI / M_w), 1.0, 1e-5);

  EversionRobot banded(Vine({{0.4, 0.45, 0.5, 0.36}}), L, p);
  const BendRadiusResult b = MinimumBendRadius(banded, StaticLoads{}, moment);
  ASSERT_EQ(b.limit, "kink");
  EXPECT_GE(b.s, 0.4);  // the band kinks, at 1/8 of the moment
  EXPECT_LE(b.s, 0.45);
  EXPECT_NEAR(b.load_factor, 0.5 / 8, 1e-5);
  EXPECT_NEAR(b.min_radius / a.min_radius, 0.36, 1e-4);
  EXPECT_LT(b.min_radius, a.min_radius);
}

TEST(BendRadius, ActuationLimitWhenTheLoadStaysBelowTheKink) {
  const double p = 3e3, r = 0.025;
  const double M_w = truth::WrinklingMoment(p, r);
  StaticLoads moment;
  moment.tip_moment = Vec3(0.5 * M_w, 0, 0);
  EversionRobot plain(Vine({}), 1.0, p);
  const BendRadiusResult a = MinimumBendRadius(plain, StaticLoads{}, moment, 4);
  EXPECT_EQ(a.limit, "actuation");
  EXPECT_EQ(a.load_factor, 1.0);
}

// Layer jamming (Do et al. 2023): a vine with its proximal half jammed to α = 4 times
// the tube's EI (E_ℓ I_ℓ = 3 EI_tube). Under a pure tip moment M the curvature is M/EI(s) section
// by section (the moment is uniform; the pressure only pre-stretches the wall): jamming does not
// change the compliant half's radius at a given moment, so the kink-limited radius (at M = M_w,
// the tube's wrinkling moment everywhere) is the plain tube's. For a given turn θ of the tip,
// θ = M ∫ds/EI, the bend concentrates in the compliant half: its radius is (1 − f + f/α) L/θ =
// 0.625 L/θ, between the rigid-jamming bound (1 − f) L/θ and the plain L/θ, reached with 1/0.625
// times the moment (so the jammed vine kinks at a 0.625 times smaller turn). Pure bending of a
// piecewise-uniform rod is integrated exactly by RK4 (jamming ends are nodes) and the angle is
// solved to 1e-10 rad: 1e-6 is generous.
TEST(BendRadius, JammingConcentratesAGivenTurnInTheCompliantSegments) {
  const double p = 3e3, L = 1.0, r = 0.025, t = 75e-6;
  const double EI = (100e6 + 1e4 * p) * kPi * r * r * r * t;
  const double f = 0.5, alpha = 4.0, layer_I = 1e-10;
  EversionRobotDesign jammed_design = Vine({});
  jammed_design.jamming = {JammingSegment{0.0, f * L, layer_I,
                                          ModulusLaw::Affine(0.0, 3 * EI / layer_I / 1e4)}};
  EversionRobot jammed(jammed_design, L, p);
  jammed.SetJammingPressure(0, 1e4);  // E_ℓ(1e4 Pa) I_ℓ = 3 EI
  EXPECT_NEAR(jammed.BendingStiffnessAt(0.25) / jammed.BendingStiffnessAt(0.75), alpha, 1e-12);
  EversionRobot plain(Vine({}), L, p);

  StaticLoads moment;
  moment.tip_moment = Vec3(0, 0.01, 0);  // a unit pattern: λ scales it
  const double theta = 0.05;             // rad: below both kinks (the plain vine's is at 0.154)
  const BendRadiusResult a = BendRadiusAtTipAngle(plain, StaticLoads{}, moment, theta);
  const BendRadiusResult b = BendRadiusAtTipAngle(jammed, StaticLoads{}, moment, theta);
  ASSERT_EQ(a.limit, "angle");
  ASSERT_EQ(b.limit, "angle");
  std::printf("turn %.3f rad: plain R_min = %.5f m, jammed half R_min = %.5f m at s = %.3f m "
              "(ratio %.6f, closed form %.6f); kink ratio %.3f vs %.3f\n",
              theta, a.min_radius, b.min_radius, b.s, b.min_radius / a.min_radius,
              1 - f + f / alpha, a.kink_ratio, b.kink_ratio);
  EXPECT_NEAR(a.min_radius, L / theta, 1e-6 * L / theta);
  EXPECT_NEAR(b.min_radius / a.min_radius, 1 - f + f / alpha, 1e-6);
  EXPECT_GT(b.min_radius, (1 - f) * L / theta);  // the rigid-jamming bound
  EXPECT_GE(b.s, f * L);                         // in the compliant half
  EXPECT_NEAR(b.kink_ratio / a.kink_ratio, 1 / (1 - f + f / alpha), 1e-6);
  EXPECT_NEAR(b.load_factor / a.load_factor, 1 / (1 - f + f / alpha), 1e-6);

  // Kink-limited: the same radius as the plain tube, EI/M_w, in the compliant half.
  const double M_w = truth::WrinklingMoment(p, r);
  StaticLoads to_kink;
  to_kink.tip_moment = Vec3(0, 2 * M_w, 0);
  const BendRadiusResult c = MinimumBendRadius(jammed, StaticLoads{}, to_kink);
  ASSERT_EQ(c.limit, "kink");
  EXPECT_NEAR(c.min_radius / (EI / M_w), 1.0, 1e-5);
  EXPECT_GE(c.s, f * L);

  EXPECT_THROW(BendRadiusAtTipAngle(plain, StaticLoads{}, moment, 4.0), std::invalid_argument);
  EXPECT_THROW(jammed.SetJammingPressure(1, 1e4), std::invalid_argument);
  EXPECT_THROW(jammed.SetJammingPressure(0, -1), std::invalid_argument);
  // A jamming segment past the stored tube, or over a band, is refused naming the field.
  auto message = [&](const EversionRobotDesign& d) -> std::string {
    try {
      EversionRobot robot(d, L, p);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EversionRobotDesign bad = jammed_design;
  bad.jamming[0].end = 2 * L;
  EXPECT_EQ(message(bad).rfind("jamming", 0), 0u) << message(bad);
  bad = jammed_design;
  bad.bands = {{0.4, 0.45, 0.5, 0.36}};
  EXPECT_EQ(message(bad).rfind("jamming[0]", 0), 0u) << message(bad);
}

}  // namespace
}  // namespace cosserat
