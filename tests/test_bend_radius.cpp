// Minimum bend radius of an eversion robot against the closed form: under a growing pure tip
// moment the body first kinks where M reaches the wrinkling moment M_w(s) = π p r(s)³/2, and its
// radius there is EI(s)/M_w(s). With seed 003's bands (EI = α E_eff I(s), I and M_w both ∝ r³)
// that is α times the plain tube's: bands give the tighter bend, as in the experiments.
#include <gtest/gtest.h>

#include <cmath>

#include "cosserat/analysis/bend_radius.hpp"

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
  const double M_w = kPi * p * r * r * r / 2;
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
  const double M_w = kPi * p * r * r * r / 2;
  StaticLoads moment;
  moment.tip_moment = Vec3(0.5 * M_w, 0, 0);
  EversionRobot plain(Vine({}), 1.0, p);
  const BendRadiusResult a = MinimumBendRadius(plain, StaticLoads{}, moment, 4);
  EXPECT_EQ(a.limit, "actuation");
  EXPECT_EQ(a.load_factor, 1.0);
}

}  // namespace
}  // namespace cosserat
