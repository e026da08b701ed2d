// Static shooting solver against the truth: the elastica table, the pure-moment circle,
// Timoshenko shear deflection, axial stretch, and the 4th-order convergence of RK4 in s.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/constant_curvature.hpp"
#include "support/analytic/elastica.hpp"
#include "support/analytic/timoshenko_beam.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using truth::kPi;

nlohmann::json LoadReference(const std::string& name) {
  std::ifstream in(std::string(COSSERAT_REFERENCE_DIR) + "/" + name);
  EXPECT_TRUE(in.good()) << "missing reference file " << name;
  return nlohmann::json::parse(in);
}

// A slender steel rod along +z, clamped at the origin. r/L = 1/200 so the extensible, shearable
// rod differs from the inextensible elastica by about alpha (r/L)^2 / 4 < 1e-4 (reference notes).
struct SlenderRod : testing::SteelRod {
  SlenderRod() : testing::SteelRod{1.0, 0.005} {}
};

TEST(StaticVerification, ElasticaTableAtN41) {
  const nlohmann::json ref = LoadReference("elastica_tip_load.json");
  SlenderRod rod;
  StaticShootingSolver solver(rod.model(), 41);
  ASSERT_GE(ref["rows"].size(), 6u);
  for (const auto& row : ref["rows"]) {
    const double alpha = row["alpha"];
    StaticLoads loads;
    loads.tip_force =
        Vec3(-alpha * rod.EI() / (rod.length * rod.length), 0, 0);  // dead load along −x
    solver.ResetWarmStart();  // every row from a cold start
    const auto summary = solver.Solve(lie::SE3{}, loads);
    ASSERT_TRUE(summary.converged()) << "alpha " << alpha << ": " << ToString(summary.status);
    const Vec3 tip = solver.state().tip_position_W();
    // Acceptance: 1e-3 L. RK4 at h = L/40 and the (r/L)^2 model difference are both far below.
    EXPECT_NEAR(-tip.x() / rod.length, row["deflection_over_L"].get<double>(), 1e-3) << alpha;
    EXPECT_NEAR(tip.z() / rod.length, row["axial_over_L"].get<double>(), 1e-3) << alpha;
    const Vec3 t = solver.state().tip_rotation_WB().col(2);
    const double angle_deg = std::atan2(-t.x(), t.z()) * 180.0 / kPi;
    EXPECT_NEAR(angle_deg, row["tip_angle_deg"].get<double>(), 0.06) << alpha;  // 1e-3 rad
  }
}

// The elastica closed form of the reference file (Bisshopp & Drucker), for loads beyond the
// table: truth::TipLoadElasticaDeflection.
using truth::TipLoadElasticaDeflection;

// Large loads have several equilibria (folded ones among them). A cold solve must land on the
// natural branch, the one reached by loading from zero.
TEST(StaticVerification, LargeLoadsFollowTheNaturalBranch) {
  // The closed form reproduces the table first, so it can be trusted beyond it.
  EXPECT_NEAR(TipLoadElasticaDeflection(10), 0.8106090249, 1e-8);
  SlenderRod rod;
  for (double alpha : {20.0, 50.0}) {
    StaticShootingSolver solver(rod.model(), 41);
    StaticLoads loads;
    loads.tip_force = Vec3(-alpha * rod.EI() / (rod.length * rod.length), 0, 0);
    const auto summary = solver.Solve(lie::SE3{}, loads);
    ASSERT_TRUE(summary.converged()) << alpha;
    // Model difference (r/L)² α/4 ≈ 3e-4 at α = 50 (the stretch under the load) plus RK4 error:
    // within 1e-3 L, as for the table.
    EXPECT_NEAR(-solver.state().tip_position_W().x() / rod.length, TipLoadElasticaDeflection(alpha),
                1e-3)
        << alpha;
  }
}

// Pure end moment M about body y: a circular arc of curvature M/EI (exact, no shear or stretch).
TEST(StaticVerification, EndMomentClosesCircle) {
  SlenderRod rod;
  StaticShootingSolver solver(rod.model(), 41);
  StaticLoads loads;
  loads.tip_moment = Vec3(0, truth::EndMomentForTurn(2 * kPi, rod.EI(), rod.length), 0);
  const auto summary = solver.Solve(lie::SE3{}, loads);
  ASSERT_TRUE(summary.converged());
  // The arc has curvature exactly M/EI; the only error is RK4's O(h^4) ~ (2π/40)^4/120 L ≈ 5e-6 L
  // at worst, and in practice far less. Acceptance asks 1e-4 L.
  EXPECT_LT(solver.state().tip_position_W().norm(), 1e-4 * rod.length);
}

TEST(StaticVerification, EndMomentHalfCircle) {
  SlenderRod rod;
  StaticShootingSolver solver(rod.model(), 41);
  StaticLoads loads;
  loads.tip_moment = Vec3(0, truth::EndMomentForTurn(kPi, rod.EI(), rod.length), 0);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  const RodState& st = solver.state();
  const double radius = rod.length / kPi;
  // Positive moment about y turns the tangent e3 towards +x: centre at (radius, 0, 0).
  const Vec3 centre(radius, 0, 0);
  for (int i = 0; i < st.size(); ++i)
    EXPECT_NEAR((st.position_W[i] - centre).norm(), radius, 1e-6 * rod.length) << "node " << i;
  EXPECT_NEAR(st.tip_position_W().norm(), 2 * radius, 1e-6 * rod.length);
  EXPECT_NEAR(st.tip_position_W().x(), 2 * radius, 1e-6 * rod.length);
}

// Short, thick rod (L/r = 10): the Timoshenko tip deflection PL³/(3EI) + PL/(κGA).
TEST(StaticVerification, TimoshenkoShearDeflection) {
  const double L = 0.1, r = 0.01;
  const Material mat = Material::FromPoissonRatio(200e9, 0.3, 7800);
  const CrossSection sec = CrossSection::Circle(r);
  StaticShootingOptions opt;
  opt.tolerance = 1e-14;
  StaticShootingSolver solver(RodModel::Uniform(L, sec, mat), 41, opt);
  const double EI = mat.youngs_modulus * sec.I1;
  const double kGA = sec.ShearCoefficient(0.3) * mat.shear_modulus * sec.area;
  // Small load: δ/L ≈ 1e-6, so geometric nonlinearity contributes ~(δ/L)² ≈ 1e-12 relative.
  const double P = 1e-6 * 3 * EI / (L * L);
  StaticLoads loads;
  loads.tip_force = Vec3(P, 0, 0);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  const double expected = truth::CantileverTipDeflection(P, L, EI, kGA);
  const double shear_part = P * L / kGA;
  ASSERT_GT(shear_part / expected, 0.01);  // the shear term is large enough to be tested
  // Linear theory is exact for this model up to (δ/L)²; RK4 integrates a cubic exactly.
  EXPECT_NEAR(solver.state().tip_position_W().x(), expected, 1e-7 * expected);
}

TEST(StaticVerification, AxialStretchUnderAxialLoad) {
  SlenderRod rod;
  StaticShootingOptions opt;
  opt.tolerance = 1e-14;
  StaticShootingSolver solver(rod.model(), 41, opt);
  const double EA = rod.EA();
  const double P = 1e-3 * EA;  // 0.1 % strain
  StaticLoads loads;
  loads.tip_force = Vec3(0, 0, P);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  // Γ3 = 1 + P/EA exactly along the rod: the stretch is PL/(EA) to round-off.
  // Round-off of summing 40 steps of length ~L/40 is ~1e-15 L against a stretch of 1e-3 L.
  EXPECT_NEAR(solver.state().tip_position_W().z() - rod.length, P * rod.length / EA,
              1e-9 * P * rod.length / EA);
}

// Rest curvature k about y and no load: a circular arc of radius 1/k.
TEST(StaticVerification, RestCurvatureGivesArcUnderNoLoad) {
  SlenderRod rod;
  RodModel model = rod.model();
  const double k = 2.0;  // 1/m
  model.rest_strain = ConstantRestCurvature(Vec3(0, k, 0));
  StaticShootingSolver solver(model, 41);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, StaticLoads{}).converged());
  const Vec3 expected = truth::ArcPoint(k, rod.length);
  // RK4 on R' = R K̂ with constant K truncates exp(hK̂) after the 4th power: (kh)^5/120 =
  // 2.6e-9 rad per step, 1e-7 rad over 40 steps, so the tip is off by about 5e-8 L.
  EXPECT_LT((solver.state().tip_position_W() - expected).norm(), 2e-7 * rod.length);
}

// Refinement in N: the tip error of RK4 falls as h⁴. A nonlinear case (gravity plus a tip load,
// both large) against a fine-grid solution (N = 513, error ~1e-4 of the coarsest).
TEST(StaticVerification, FourthOrderConvergenceInN) {
  SlenderRod rod;
  StaticShootingOptions opt;
  opt.tolerance = 1e-14;
  StaticLoads loads;
  loads.tip_force = Vec3(-2 * rod.EI(), 0, 0.5 * rod.EI());
  loads.gravity_W = Vec3(0, -9.81 * 40, 0);
  auto tip = [&](int n) {
    StaticShootingSolver solver(rod.model(), n, opt);
    const auto summary = solver.Solve(lie::SE3{}, loads);
    EXPECT_TRUE(summary.converged()) << n;
    return Vec3(solver.state().tip_position_W());
  };
  const Vec3 reference = tip(513);
  std::vector<double> log_h, log_e;
  for (int n : {5, 9, 17, 33}) {
    log_h.push_back(std::log(1.0 / (n - 1)));
    log_e.push_back(std::log((tip(n) - reference).norm()));
  }
  // Least-squares slope of log e against log h.
  const double mh = (log_h[0] + log_h[1] + log_h[2] + log_h[3]) / 4;
  const double me = (log_e[0] + log_e[1] + log_e[2] + log_e[3]) / 4;
  double num = 0, den = 0;
  for (int i = 0; i < 4; ++i) {
    num += (log_h[i] - mh) * (log_e[i] - me);
    den += (log_h[i] - mh) * (log_h[i] - mh);
  }
  const double order = num / den;
  EXPECT_NEAR(order, 4.0, 0.3) << "observed order " << order;
}

}  // namespace
}  // namespace cosserat
