// The stability index of column equilibria (ColumnSolver::StabilityIndexFromShot) and the buckling
// scan it steers, against the truth: Euler's critical loads for each pair of ends, the energy
// argument for a beam sagging under its weight, and the Winkler roots of a pipe lying in a bore
// (Dawson & Paslay 1984: a pipe on the low side of a hole is held laterally by its weight).
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/analysis/buckling.hpp"
#include "cosserat/analysis/buckling_in_pieces.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/strong/pinned_base.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/roots.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The k-th positive root of tan x = x (k = 1, 2, …), in (kπ, kπ + π/2).
double TanRoot(int k) {
  return truth::Bisect([](double x) { return std::sin(x) - x * std::cos(x); }, k * kPi,
                       (k + 0.5) * kPi);
}

// The first critical loads of the straight inextensible column, P L²/EI, in order (Timoshenko &
// Gere 1961): pinned–pinned (kπ)²; clamped–clamped (2kπ)² (symmetric) and (2 x_k)² with
// tan x_k = x_k (antisymmetric); clamped–pinned x_k²; clamped–free ((2k − 1)π/2)².
std::vector<double> EulerLoadParameters(ColumnEnds ends) {
  switch (ends) {
    case ColumnEnds::kPinnedPinned:
      return {kPi * kPi, 4 * kPi * kPi, 9 * kPi * kPi};
    case ColumnEnds::kClampedClamped:
      return {4 * kPi * kPi, 4 * TanRoot(1) * TanRoot(1), 16 * kPi * kPi};
    case ColumnEnds::kClampedPinned:
      return {TanRoot(1) * TanRoot(1), TanRoot(2) * TanRoot(2), TanRoot(3) * TanRoot(3)};
    case ColumnEnds::kClampedFree:
      return {kPi * kPi / 4, 9 * kPi * kPi / 4, 25 * kPi * kPi / 4};
  }
  return {};
}

// The index of the equilibrium at u under loads, from one shot.
int IndexAt(const ColumnSolver& column, const StaticLoads& loads, const Vec6& u) {
  RodState record;
  std::vector<ColumnSolver::StateTangent> tangents;
  column.Residual(lie::SE3{}, loads, u, nullptr, &record, &tangents);
  return column.StabilityIndexFromShot(lie::SE3{}, loads, u, record, tangents);
}

// A round steel column (r/L = 1/200) pressed straight: below the first Euler load it is stable,
// and past each one it has two more unstable directions (it buckles alike in any plane). The
// loads tested sit halfway (geometrically) between Euler loads, far outside the 5e-4 the column's
// shear and shortening move them by.
TEST(ColumnStability, IndexCountsTheEulerLoadsBelowTheLoadForEveryPairOfEnds) {
  const testing::SteelRod rod{1.0, 0.005};
  for (ColumnEnds ends : {ColumnEnds::kPinnedPinned, ColumnEnds::kClampedClamped,
                          ColumnEnds::kClampedPinned, ColumnEnds::kClampedFree}) {
    ColumnSolver column(rod.model(), 61, ends);
    const std::vector<double> roots = EulerLoadParameters(ends);
    std::vector<double> ratios{0.5 * roots[0]};
    for (size_t k = 0; k + 1 < roots.size(); ++k)
      ratios.push_back(std::sqrt(roots[k] * roots[k + 1]));
    ratios.push_back(1.2 * roots.back());
    for (double ratio : ratios) {
      const double P = ratio * rod.EI() / (rod.length * rod.length);
      StaticLoads loads;
      loads.tip_force = Vec3(0, 0, -P);
      // The straight state: no moments, the axial force n(0) = −P e₃ (each end's unknowns hold
      // the base force in their last three entries, scaled).
      Vec6 u = Vec6::Zero();
      u(5) = -P / column.scale()(5);
      ASSERT_LT(column.Residual(lie::SE3{}, loads, u).norm(), 1e-12) << ToString(ends);
      int below = 0;
      for (double root : roots) below += root < ratio;
      EXPECT_EQ(IndexAt(column, loads, u), 2 * below) << ToString(ends) << " at " << ratio;
    }
  }
}

// The k-th critical load parameter P L²/EI (k = 1, 2, …) of the straight inextensible column,
// as EulerLoadParameters, for any k: clamped–clamped merges its symmetric and antisymmetric
// families, which alternate.
double EulerLoadParameter(ColumnEnds ends, int k) {
  switch (ends) {
    case ColumnEnds::kPinnedPinned:
      return k * k * kPi * kPi;
    case ColumnEnds::kClampedClamped: {
      const int j = (k + 1) / 2;
      return k % 2 == 1 ? 4 * j * j * kPi * kPi : 4 * TanRoot(j) * TanRoot(j);
    }
    case ColumnEnds::kClampedPinned:
      return TanRoot(k) * TanRoot(k);
    case ColumnEnds::kClampedFree:
      return (2 * k - 1) * (2 * k - 1) * kPi * kPi / 4;
  }
  return 0;
}

// Far past the first Euler loads (13 of them: about 180 P_E for a pinned column) the Jacobi
// fields turn 14 times along the rod, and between two nodes a circular section's two conjugate
// points turn the Prüfer angles a whole circle each unless their scale c is chosen with care: an
// index read with too large a c missed pairs of them. The count must hold from one shot and from
// fields carried through pieces alike. 201 nodes give 14 per half-wave; the load sits halfway
// (geometrically) between the 13th and 14th critical loads, which shear and shortening move by
// about 1e-2 here ((kr)² with k = 14π/L).
TEST(ColumnStability, IndexCountsManyEulerLoadsFromOneShotAndInPieces) {
  const testing::SteelRod rod{1.0, 0.005};
  for (ColumnEnds ends : {ColumnEnds::kPinnedPinned, ColumnEnds::kClampedClamped,
                          ColumnEnds::kClampedPinned, ColumnEnds::kClampedFree}) {
    ColumnSolver column(rod.model(), 201, ends);
    const double ratio =
        std::sqrt(EulerLoadParameter(ends, 13) * EulerLoadParameter(ends, 14));
    const double P = ratio * rod.EI() / (rod.length * rod.length);
    StaticLoads loads;
    loads.tip_force = Vec3(0, 0, -P);
    Vec6 u = Vec6::Zero();
    u(5) = -P / column.scale()(5);
    RodState record;
    std::vector<ColumnSolver::StateTangent> tangents;
    ASSERT_LT(column.Residual(lie::SE3{}, loads, u, nullptr, &record, &tangents).norm(), 1e-10);
    EXPECT_EQ(column.StabilityIndexFromShot(lie::SE3{}, loads, u, record, tangents), 26)
        << ToString(ends);
    for (int pieces : {4, 9}) {
      EXPECT_EQ(column.StabilityIndexInPieces(lie::SE3{}, loads, record, pieces), 26)
          << ToString(ends) << " in " << pieces << " pieces";
    }
  }
}

// A round steel cantilever bent past its Euler load (1.5 P_E, a 1 % side load) on its stable
// buckled branch: 0 through the single shot's count and through the column solver's with the
// threshold the statics in pieces give it (1e-8 EI/L). Its marginal direction (the shape turned
// about the load's axis) lands on the positive side here, so this checks the count, not the
// threshold.
TEST(ColumnStability, ABuckledRoundCantileverCountsAlikeThroughEitherSolver) {
  const testing::SteelRod rod{1.0, 0.005};
  const double P = 1.5 * kPi * kPi / 4 * rod.EI() / (rod.length * rod.length);
  StaticLoads loads;
  loads.tip_force = Vec3(0.01 * P, 0, -P);
  StaticShootingSolver single(rod.model(), 61);
  ASSERT_TRUE(single.Solve(lie::SE3{}, loads).converged());
  const Vec6 W0 = single.base_wrench_B();
  EXPECT_EQ(single.StabilityIndex(lie::SE3{}, loads, W0), 0);
  const ColumnSolver column(rod.model(), 61, ColumnEnds::kClampedFree);
  const Vec6 u = W0.cwiseQuotient(column.scale());
  RodState record;
  std::vector<ColumnSolver::StateTangent> tangents;
  ASSERT_LT(column.Residual(lie::SE3{}, loads, u, nullptr, &record, &tangents).norm(), 1e-8);
  EXPECT_EQ(column.StabilityIndexFromShot(lie::SE3{}, loads, u, record, tangents, 1e-8), 0);
}

// The pin's twist axis is normal to the rotations the pin allows, R_WB Exp([a, b, 0]), whose
// body-frame directions are J_r(θ) e₀ and J_r(θ) e₁: to rounding (1e-14) at angles up to 3 rad,
// and on both sides of t = 1e-2, where its series gives way to the closed form.
TEST(ColumnStability, ThePinsTwistAxisIsNormalToTheRotationsItAllows) {
  for (const double t : {0.0, 1e-6, 0.0099999, 0.0100001, 0.3, 1.0, 2.0, 3.0}) {
    for (const double phi : {0.0, 0.7, 2.5}) {
      const Vec3 theta(t * std::cos(phi), t * std::sin(phi), 0.0);
      const Vec3 nu = PinnedTwistAxis(theta(0), theta(1));
      const Mat3 Jr = lie::SO3RightJacobian(theta);
      EXPECT_NEAR(nu.dot(Jr.col(0)), 0.0, 1e-14) << t << " " << phi;
      EXPECT_NEAR(nu.dot(Jr.col(1)), 0.0, 1e-14) << t << " " << phi;
      EXPECT_NEAR(nu.dot(Jr.col(2)), 1.0, 1e-14) << t << " " << phi;  // ν = J_r⁻ᵀ e₃
    }
  }
}

// A pinned column bent on its stable branch by a side load (2 % of P_E per length L, along y)
// and pressed from 0.1 to 2.1 P_E, its pins still apart (the elastica's chord is 0.03 L at
// 2.1 P_E): round, and a flat bar soft across y. Its index must stay 0. On the round column the
// Jacobian of the column's residual stays regular on the way (det J > 0), and the index can
// change only where the second variation, and with it J, is singular. The base turns by up to
// 2 rad here: Jacobi fields started with the pin's torque along the section's axis instead of
// the pin's twist axis (pinned_base.hpp) are no Lagrangian subspace, and counted the round
// column unstable from 1.12 P_E and the bar from 1.4 P_E.
TEST(ColumnStability, APinnedColumnBentOnItsStableBranchCountsStable) {
  for (const bool round : {true, false}) {
    const CrossSection c =
        round ? CrossSection::Circle(0.001) : CrossSection::Rectangle(0.01, 0.001);
    const RodModel model =
        RodModel::Uniform(0.5, c, Material::FromShearModulus(200e9, 80e9, 8000));
    const double PE = kPi * kPi * 200e9 * c.I1 / 0.25;
    ColumnSolver column(model, 61, ColumnEnds::kPinnedPinned);
    StaticLoads side;
    side.distributed_force_W = Vec3(0, 0.02 * PE / 0.5, 0);
    ASSERT_TRUE(column.SolveFromUnloaded(lie::SE3{}, side).converged());
    for (double ratio = 0.1; ratio < 2.12; ratio += 0.05) {
      StaticLoads loads = side;
      loads.tip_force = Vec3(0, 0, -ratio * PE);
      ASSERT_TRUE(column.Solve(lie::SE3{}, loads).converged()) << ratio;
      Mat6 J;
      RodState record;
      std::vector<ColumnSolver::StateTangent> tangents;
      column.Residual(lie::SE3{}, loads, column.unknowns(), &J, &record, &tangents);
      if (round) EXPECT_GT(J.determinant(), 0.0) << ratio;
      EXPECT_EQ(column.StabilityIndexFromShot(lie::SE3{}, loads, column.unknowns(), record,
                                              tangents),
                0)
          << (round ? "round " : "bar ") << ratio;
    }
    EXPECT_GT(column.state().position_W.back()(2), 0.0);  // the pins still apart
  }
}

// A 30 m steel pipe sagging under its own weight between its supports is at the minimum of its
// energy: no unstable direction, for every pair of ends. (Its sag, 2 m between pins, turns one
// eigenvalue of the tip stiffness of the pinned rod's first metres negative and back, which a
// count of eigenvalue drops took for a conjugate point.)
TEST(ColumnStability, APipeSaggingUnderItsWeightIsStable) {
  const CrossSection pipe = CrossSection::Annulus(0.0635, 0.054);
  const RodModel model =
      RodModel::Uniform(30.0, pipe, Material::FromPoissonRatio(200e9, 0.3, 7850));
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);  // across the column (its axis is +z)
  for (ColumnEnds ends : {ColumnEnds::kPinnedPinned, ColumnEnds::kClampedClamped,
                          ColumnEnds::kClampedPinned}) {
    ColumnSolver column(model, 121, ends);
    ASSERT_TRUE(column.SolveFromUnloaded(lie::SE3{}, loads).converged()) << ToString(ends);
    EXPECT_GT(column.state().position_W[60].norm(), 0.0);
    EXPECT_EQ(IndexAt(column, loads, column.unknowns()), 0) << ToString(ends);
  }
}

std::string Number(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

// A steel pipe (outer radius 0.0635 m, inner 0.054 m) of length L lying along +x on the low side
// of a horizontal bore of radius 0.108 m (penalty stiffness 2e4 N/m per m), pinned at both ends
// at the height `pin_depth` below the line where it touches the bore, pressed along its axis.
io::Problem PipeInBore(double L, double pin_depth) {
  const std::string text = R"({"format": "cosserat-problem/1", "analysis": "buckling",
    "rod": {"length": )" + Number(L) + R"(, "nodes": 125,
      "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.054},
      "material": {"youngs_modulus": 200e9, "poisson_ratio": 0.3, "density": 7850}},
    "base": {"position": [0, 0, 0], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
    "boundary": "pinned-pinned",
    "loads": {"gravity": [0, 0, -9.81]},
    "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, )" +
                           Number(0.0445 + pin_depth) + R"(], "axis": [1, 0, 0],
      "radius": 0.108, "side": "inside", "stiffness": 2e4}]},
    "buckling": {"load": "tip_force", "direction": [-1, 0, 0], "max": 400000}})";
  const io::ParseResult parsed = io::ParseProblem(text);
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  return *parsed.problem;
}

BucklingAnalysis AnalysisOf(const io::Problem& p) {
  BucklingOptions options;
  options.lambda_max = p.buckling.max;
  LoadPath path = LoadPath::TipForce(p.buckling.direction);
  path.fixed = p.loads;
  return BucklingAnalysis(p.rod, p.nodes, ColumnEnds::kPinnedPinned, p.base, path, options);
}

// Pinned at the depth where its weight w holds it in the bore (penalty φ = δ − ε/2 = w/k, ε the
// smoothing, 1e-3 of the diameter), the pipe lies straight on a uniform Winkler foundation
// across it: pushed sideways by y its centreline, at d = clearance + δ from the bore's axis, is
// pulled back by w y/d. Its lateral modes sin(nπx/L) buckle at P_n = EI a² + (w/d)/a², a = nπ/L.
// At L = 31 m the second and third are 0.2 % apart, both inside one scan step (1e4 N), where det
// J changes sign twice and keeps it; the search must report the lower one, which the index,
// rising by 2 across the step, is bisected to. The model's shear and shortening move P by about
// P/κGA + P/EA ≈ 1.3e-3: tolerance 0.5 %.
TEST(ColumnStability, APipeInABoreBucklesAtTheLowerOfTwoCloseWinklerRoots) {
  const double L = 31, E = 200e9, ro = 0.0635, ri = 0.054;
  const double EI = E * kPi / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
  const double w = 7850 * kPi * (ro * ro - ri * ri) * 9.81;  // N/m
  const double eps = 1e-3 * 2 * ro, delta = w / 2e4 + 0.5 * eps;
  const double k_lateral = w / (0.0445 + delta);  // N/m per m
  std::vector<double> P;
  for (int n = 1; n <= 4; ++n) {
    const double a = n * kPi / L;
    P.push_back(EI * a * a + k_lateral / (a * a));
  }
  const double lowest = std::min(P[1], P[2]);
  ASSERT_LT(std::abs(P[1] - P[2]), 400000.0 / 40);  // within one scan step
  ASSERT_LT(lowest, std::min(P[0], P[3]));

  BucklingAnalysis analysis = AnalysisOf(PipeInBore(L, delta));
  const BucklingSummary b = analysis.FindCriticalLoad();
  ASSERT_TRUE(b.found()) << ToString(b.status);
  EXPECT_NEAR(b.critical_load / lowest, 1.0, 5e-3) << b.critical_load << " vs " << lowest;
  // The mode is lateral (y), not in the vertical plane.
  double lateral = 0, vertical = 0;
  for (const Vec3& d : b.mode.displacement_W) {
    lateral = std::max(lateral, std::abs(d.y()));
    vertical = std::max(vertical, std::abs(d.z()));
  }
  EXPECT_GT(lateral, 100 * vertical);
}

// Pinned on the line where it touches the bore, the pipe sinks between its pins into the
// penalty, and the preload (its weight) is a path of its own. The critical load the search
// reports must end a path of stable equilibria: just below it the pipe, still resting in the
// bore, has no unstable direction (loaded at once from straight, Newton had landed on an
// unstable equilibrium, and the search reported a load 1.8 times too high from there).
TEST(ColumnStability, APipeRestingInABoreIsStableUpToItsCriticalLoad) {
  const io::Problem p = PipeInBore(30, 0.0);
  BucklingAnalysis analysis = AnalysisOf(p);
  const BucklingSummary b = analysis.FindCriticalLoad();
  ASSERT_TRUE(b.found()) << ToString(b.status);
  const double below = 0.98 * b.critical_load;
  ColumnSolver column(p.rod, p.nodes, ColumnEnds::kPinnedPinned);
  const StaticLoads loads = analysis.path().LoadsAt(below);
  column.set_unknowns(analysis.column().unknowns());
  ASSERT_TRUE(column.Solve(p.base, loads).converged());
  RodState record;
  std::vector<ColumnSolver::StateTangent> tangents;
  column.Residual(p.base, loads, column.unknowns(), nullptr, &record, &tangents);
  EXPECT_EQ(column.StabilityIndexFromShot(p.base, loads, column.unknowns(), record, tangents), 0);
  for (const Vec3& x : record.position_W) EXPECT_LT(x.z(), 1e-9);  // resting on the bore
}

// The same search in pieces (BucklingInPieces: multiple shooting, the index from Jacobi fields
// carried piece by piece, the mode carried back through the pieces' bases) on a pipe a single
// shot still follows (30 m on a soft bore, pinned where its weight holds it: the Winkler roots
// of APipeInABoreBucklesAtTheLowerOfTwoCloseWinklerRoots's kind): the same discrete equations,
// so the same critical load to the bisections' and solves' tolerances (1e-8 of it) and the same
// mode (to 1e-5 of its unit amplitude).
TEST(ColumnStability, TheSearchInPiecesAgreesWithTheSingleShot) {
  const double w = 7850 * kPi * (0.0635 * 0.0635 - 0.054 * 0.054) * 9.81;
  const io::Problem p = PipeInBore(30, w / 2e4 + 0.5e-3 * 0.127);
  BucklingAnalysis single = AnalysisOf(p);
  const BucklingSummary a = single.FindCriticalLoad();
  ASSERT_TRUE(a.found()) << ToString(a.status);
  BucklingOptions options;
  options.lambda_max = p.buckling.max;
  LoadPath path = LoadPath::TipForce(p.buckling.direction);
  path.fixed = p.loads;
  BucklingInPieces split(p.rod, p.nodes, ColumnEnds::kPinnedPinned, p.base, path, options);
  const BucklingSummary b = split.FindCriticalLoad();
  ASSERT_TRUE(b.found()) << ToString(b.status);
  EXPECT_GT(split.pieces(), 1);
  EXPECT_LT(b.critical_load_bracket, 1e-9 * b.critical_load);  // refined, not cut short
  EXPECT_NEAR(b.critical_load / a.critical_load, 1.0, 1e-8);
  double worst = 0;
  for (size_t i = 0; i < a.mode.displacement_W.size(); ++i)
    worst = std::max(worst, (a.mode.displacement_W[i] - b.mode.displacement_W[i]).norm());
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace cosserat
