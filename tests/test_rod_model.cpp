// Cross-sections, materials, sectional matrices and the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cosserat/lie/so3.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/rod/rest_shape.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/resampled_state.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/constant_curvature.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(CrossSection, ClosedFormProperties) {
  const CrossSection c = CrossSection::Circle(0.002);
  EXPECT_DOUBLE_EQ(c.area, kPi * 4e-6);
  EXPECT_DOUBLE_EQ(c.I1, kPi * 16e-12 / 4);
  EXPECT_DOUBLE_EQ(c.torsion_constant, 2 * c.I1);
  const CrossSection a = CrossSection::Annulus(0.002, 0.001);
  EXPECT_DOUBLE_EQ(a.area, kPi * 3e-6);
  EXPECT_DOUBLE_EQ(a.I1, kPi * 15e-12 / 4);
  const CrossSection r = CrossSection::Rectangle(0.004, 0.001);  // width along x, height along y
  EXPECT_DOUBLE_EQ(r.I1, 0.004 * 1e-9 / 12);
  EXPECT_DOUBLE_EQ(r.I2, 0.001 * 64e-9 / 12);
  // Thin strip limit of the Saint-Venant constant: J → w h³/3 (1 − 0.63 h/w); at w/h = 4, within
  // 1 % of the tabulated β = 0.281 (Timoshenko & Goodier): J = β w h³.
  EXPECT_NEAR(r.torsion_constant / (0.004 * 1e-9), 0.281, 0.003);
  // Square: β = 0.1406.
  const CrossSection sq = CrossSection::Rectangle(0.001, 0.001);
  EXPECT_NEAR(sq.torsion_constant / 1e-12, 0.1406, 0.001);
}

TEST(CrossSection, CowperShearCoefficients) {
  EXPECT_NEAR(CrossSection::Circle(1).ShearCoefficient(0.3), 6 * 1.3 / 8.8, 1e-15);
  EXPECT_NEAR(CrossSection::Rectangle(1, 2).ShearCoefficient(0.0), 10.0 / 12.0, 1e-15);
  // Annulus with m → 0 tends to the circle.
  EXPECT_NEAR(CrossSection::Annulus(1, 1e-8).ShearCoefficient(0.3),
              CrossSection::Circle(1).ShearCoefficient(0.3), 1e-12);
}

// A negative size squares to a positive area and I, but its diameter (what drag, buoyancy,
// contact and stress read) turns negative: a rod in a current moved upstream. Refused, named.
TEST(CrossSection, NegativeSizesAreRefusedByName) {
  std::string why;
  EXPECT_TRUE(CrossSection::Circle(1e-3).IsValid(&why));
  EXPECT_FALSE(CrossSection::Circle(-1e-3).IsValid(&why));
  EXPECT_NE(why.find("radius"), std::string::npos) << why;
  EXPECT_FALSE(CrossSection::Annulus(-2e-3, 1e-3).IsValid(&why));
  EXPECT_NE(why.find("outer_radius"), std::string::npos) << why;
  EXPECT_FALSE(CrossSection::Rectangle(-1e-3, 2e-3).IsValid(&why));
  EXPECT_NE(why.find("width"), std::string::npos) << why;
  EXPECT_FALSE(CrossSection::Rectangle(1e-3, -2e-3).IsValid(&why));
  EXPECT_NE(why.find("height"), std::string::npos) << why;
  EXPECT_FALSE(CrossSection::Explicit(1e-4, 1e-9, 1e-9, 2e-9, 1.0, -0.01).IsValid(&why));
  EXPECT_NE(why.find("outer_diameter"), std::string::npos) << why;
  EXPECT_TRUE(CrossSection::Explicit(1e-4, 1e-9, 1e-9, 2e-9).IsValid(&why));
}

TEST(Material, PoissonAndValidation) {
  const Material m = Material::FromPoissonRatio(200e9, 0.25, 7800);
  EXPECT_DOUBLE_EQ(m.shear_modulus, 80e9);
  EXPECT_NEAR(m.PoissonRatio(), 0.25, 1e-15);
  std::string why;
  EXPECT_TRUE(m.IsValid(&why));
  Material bad = m;
  bad.youngs_modulus = -1;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_NE(why.find("youngs_modulus"), std::string::npos);
  bad = m;
  bad.shear_modulus = 200e9;  // ν = −0.5 is allowed, but G > E/... : check ν bound instead
  bad.shear_modulus = 50e9;   // ν = 1 is not physical
  EXPECT_FALSE(bad.IsValid(&why));
}

TEST(Actuation, ValidityNamesTheField) {
  Actuation a;
  std::string why;
  EXPECT_TRUE(a.IsValid(&why, 0));
  a.tendon_tension[1] = 2.0;
  EXPECT_TRUE(a.IsValid(&why, 2));
  EXPECT_FALSE(a.IsValid(&why, 1));  // a tension on a tendon the rod does not have
  EXPECT_EQ(why,
            "tendon_tension[1]: a tension on the tendon at index 1 (from 0), but the rod has 1 "
            "tendon");
  a.tendon_tension[1] = -1.0;  // a tendon cannot push
  EXPECT_FALSE(a.IsValid(&why, 2));
  EXPECT_EQ(why, "tendon_tension[1]: expected a finite tension >= 0 (N), got -1");
  a = Actuation();
  a.pressure = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(a.IsValid(&why));
  EXPECT_EQ(why.rfind("pressure:", 0), 0u) << why;
  a = Actuation();
  a.stiffness_scale = 0.0;
  EXPECT_FALSE(a.IsValid(nullptr));
  a = Actuation();
  a.jamming_pressure[15] = -1.0;
  EXPECT_FALSE(a.IsValid(&why));
  EXPECT_EQ(why, "jamming_pressure[15]: expected a finite pressure >= 0 (Pa), got -1");
}

TEST(SectionProperties, StiffnessAndMassDiagonals) {
  const CrossSection c = CrossSection::Circle(0.001);
  const Material m = Material::FromShearModulus(200e9, 80e9, 8000);
  const SectionProperties p = UniformSectionProperties(c, m);
  const double kappa = c.ShearCoefficient(0.25);
  EXPECT_DOUBLE_EQ(p.stiffness(0, 0), 200e9 * c.I1);
  EXPECT_DOUBLE_EQ(p.stiffness(2, 2), 80e9 * c.torsion_constant);
  EXPECT_DOUBLE_EQ(p.stiffness(3, 3), kappa * 80e9 * c.area);
  EXPECT_DOUBLE_EQ(p.stiffness(5, 5), 200e9 * c.area);
  EXPECT_DOUBLE_EQ(p.mass(5, 5), 8000 * c.area);
  EXPECT_DOUBLE_EQ(p.mass(2, 2), 8000 * 2 * c.I1);
  EXPECT_EQ((p.stiffness - Mat6(p.stiffness.diagonal().asDiagonal())).norm(), 0.0);
}

TEST(Grid, UniformWithoutBreakpoints) {
  const auto s = MakeGrid(2.0, 5, {});
  ASSERT_EQ(s.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(s[i], 0.5 * i);
}

TEST(Grid, BreakpointsBecomeNodes) {
  const auto s = MakeGrid(1.0, 41, {0.333, 0.5, 0.51, 1.5, 0.0});
  ASSERT_EQ(s.size(), 41u);
  for (double b : {0.333, 0.5, 0.51}) {
    bool found = false;
    for (double si : s) found |= std::abs(si - b) < 1e-15;
    EXPECT_TRUE(found) << b;
  }
  for (size_t i = 1; i < s.size(); ++i) EXPECT_GT(s[i], s[i - 1]);
  EXPECT_EQ(s.front(), 0.0);
  EXPECT_EQ(s.back(), 1.0);
  EXPECT_THROW(MakeGrid(1.0, 3, {0.2, 0.4, 0.6}), std::invalid_argument);
}

// A soft band [a, b) with factor α under a pure moment M: curvature M/EI outside and M/(αEI)
// inside, so the tip angle is exactly M/EI (L − w) + M/(αEI) w. The band ends are grid nodes, so
// RK4 integrates each piece without crossing a jump.
TEST(BandedSection, PureMomentBendsBandByOneOverAlpha) {
  const double L = 1.0, a = 0.3, b = 0.45, alpha = 0.36;
  auto base = std::make_shared<UniformSection>(CrossSection::Circle(0.005),
                                               Material::FromShearModulus(200e9, 80e9, 8000));
  RodModel model;
  model.length = L;
  model.section =
      std::make_shared<BandedSection>(base, std::vector<BandedSection::Band>{{a, b, alpha}});
  StaticShootingSolver solver(model, 41);
  const double EI = base->At(0, {}).stiffness(0, 0);
  const double M = 0.5 * EI / L;
  StaticLoads loads;
  loads.tip_moment = Vec3(0, M, 0);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  const Vec3 t = solver.state().tip_rotation_WB().col(2);
  const double angle = std::atan2(t.x(), t.z());
  const double expected = M / EI * (L - (b - a)) + M / (alpha * EI) * (b - a);
  // RK4 truncates exp(hK̂) after the 4th power: (κh)^5/120 per step, 4e-10 rad at κh = 0.035 in
  // the band, times 6 steps there: ~3e-9 rad.
  EXPECT_NEAR(angle, expected, 1e-8);
  // Inside the band the sampled curvature is M/(αEI).
  const RodState& st = solver.state();
  for (int i = 1; i < st.size(); ++i) {
    if (st.s[i] > a + 1e-12 && st.s[i] < b - 1e-12)
      EXPECT_NEAR(st.strain[i](1), M / (alpha * EI), 1e-9 * M / EI);
  }
}

}  // namespace
}  // namespace cosserat

namespace cosserat {
namespace {

// A constant rest curvature κ about body y: the unloaded rod is the circular arc of
// truth::ArcPoint, which the exponential of a constant strain reproduces exactly (to round-off;
// 1e-12 m on a 0.5 m rod).
TEST(RestShape, ConstantCurvatureGivesTheArc) {
  const double kappa = 4.0;
  RodModel rod = RodModel::Uniform(0.5, CrossSection::Circle(0.002),
                                   Material::FromShearModulus(200e9, 80e9, 8000));
  rod.rest_strain = [kappa](double) {
    Vec6 xi;
    xi << 0, kappa, 0, 0, 0, 1;
    return xi;
  };
  const std::vector<Vec3> line = RestCentreline_W(rod, lie::SE3{}, 51);
  ASSERT_EQ(line.size(), 51u);
  for (int i = 0; i < 51; ++i)
    EXPECT_LT((line[i] - truth::ArcPoint(kappa, 0.01 * i)).norm(), 1e-12) << "point " << i;
}

// A circular arc of curvature κ about body y: R(s) = Exp(s κ e_y), p(s) = ArcPoint(κ, s). The
// geodesic between two of its frames stays on that one-parameter subgroup, so the resampled
// rotations are the arc's own to round-off (1e-14). Positions are chords: off the arc by at most
// the sagitta h² κ / 8 of a segment h. A wrench linear in s is carried exactly. Past the tip the
// rod goes on straight along the tip's tangent.
TEST(ResampledState, CarriesAnArcOntoOtherNodesAndGrowsItStraight) {
  const double kappa = 2.0, L = 1.0;
  const int n = 11;
  const double h = L / (n - 1);
  auto frame = [kappa](double s) { return lie::SO3Exp(Vec3(0, s * kappa, 0)); };
  RodState from;
  from.Resize(n);
  for (int i = 0; i < n; ++i) {
    const double s = i * h;
    from.s[i] = s;
    from.position_W[i] = truth::ArcPoint(kappa, s);
    from.rotation_WB[i] = frame(s);
    from.strain[i] << 0, kappa, 0, 0, 0, 1;
    from.wrench_B[i] << 0, 1.0 - s, 0, 0, 0, 2.0 * s;
  }
  std::vector<double> s;
  for (int j = 0; j <= 36; ++j) s.push_back(j * 1.2 * L / 36);  // 0 … 1.2 m, past the tip
  const RodState out = ResampledState(from, s);
  ASSERT_EQ(out.size(), 37);
  const double sagitta = h * h * kappa / 8;  // 2.5 mm
  for (int j = 0; j <= 36; ++j) {
    const double sj = std::min(s[j], L);
    EXPECT_LT((out.rotation_WB[j] - frame(sj)).norm(), 1e-14) << s[j];
    EXPECT_NEAR(out.wrench_B[j](1), 1.0 - sj, 1e-14) << s[j];
    EXPECT_NEAR(out.wrench_B[j](5), 2.0 * sj, 1e-14) << s[j];
    if (s[j] <= L) {
      EXPECT_LE((out.position_W[j] - truth::ArcPoint(kappa, s[j])).norm(), sagitta * (1 + 1e-9))
          << s[j];
    } else {
      const Vec3 straight = truth::ArcPoint(kappa, L) + (s[j] - L) * frame(L).col(2);
      EXPECT_LT((out.position_W[j] - straight).norm(), 1e-14) << s[j];
    }
  }
  EXPECT_THROW(ResampledState(from, {0.0, 0.5, 0.4}), std::invalid_argument);
  EXPECT_THROW(ResampledState(from, {-0.1, 0.5}), std::invalid_argument);
  RodState one;
  one.Resize(1);
  one.s[0] = 0;
  EXPECT_THROW(ResampledState(one, {0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace cosserat
