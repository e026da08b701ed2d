// Tendon-driven rods (Rucker & Webster's model as a tendon-augmented constitutive law) against
// the truth: the exact circular arc of a straight tendon, the small-tension twist of a helical
// tendon, and global equilibrium, which tendon tension (an internal load) cannot change; a
// tendon anchored mid-rod (a two-segment robot) bends its segment only.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/robots/tendon_control.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/tendon.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using truth::kPi;

// A 0.25 m rod of radius 1 mm with tendons through disks: steel backbone, or, for the arc test,
// with shear and extension made 1e6 times stiffer ("stiff in shear and extension").
struct TendonRod : testing::SteelRod {
  TendonRod() : testing::SteelRod{0.25, 0.001} {}
  RodModel Model(std::vector<Tendon> tendons, double axial_shear_factor = 1.0) const {
    CrossSection s = section();
    s.area *= axial_shear_factor;
    RodModel m = RodModel::Uniform(length, s, material);
    m.tendons = std::move(tendons);
    return m;
  }
};

/// robots/tendon_three_tendon.json (a 0.8 mm spring-steel backbone, two straight tendons and a
/// helical one, 8 mm out); an empty problem, and a failed test, if it does not load.
io::Problem ThreeTendonRobot() {
  const io::ParseResult parsed =
      io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/robots/tendon_three_tendon.json");
  EXPECT_TRUE(parsed.ok());
  return parsed.problem.value_or(io::Problem{});
}

Actuation Tensions(std::initializer_list<double> tau) {
  Actuation a;
  int i = 0;
  for (double t : tau) a.tendon_tension[i++] = t;
  return a;
}

TEST(Tendons, StraightTendonBendsTheRodIntoTheArcOfCurvatureTauROverEI) {
  TendonRod rod;
  const double offset = 0.005;  // 5 mm from the axis, along body x
  const RodModel model = rod.Model({{"t0", TendonRoute::Parallel(Vec2(offset, 0))}}, 1e6);
  // A quarter circle: κ L = π/2.
  const double tau = truth::TendonTensionForTurn(0.5 * kPi, rod.EI(), rod.length, offset);
  StaticShootingSolver solver(model, 41, {}, Tensions({tau}));
  const auto summary = solver.Solve(lie::SE3{}, StaticLoads{});
  ASSERT_TRUE(summary.converged()) << ToString(summary.status);
  const double kappa = truth::TendonArcCurvature(tau, offset, rod.EI());
  // With Γ = (1 − τ/EA) e3 the centreline is a circle of radius (1 − τ/EA)/κ about (ρ, 0, 0),
  // bent towards the tendon (+x). τ/EA ≈ 1e-9 here.
  const double EA = rod.EA() * 1e6;
  const double radius = truth::TendonArcRadius(tau, offset, rod.EI(), EA);
  const Vec3 centre(radius, 0, 0);
  for (int i = 0; i < solver.state().size(); ++i) {
    // Acceptance 0.1 %. The arc is exact in the model; RK4 at h = L/40 integrates it with a
    // local error ~(κh)^5/120 per step (κh = π/80): ~1e-9 over the rod, so 1e-7 is ample.
    EXPECT_NEAR((solver.state().position_W[i] - centre).norm() / radius, 1.0, 1e-7) << i;
    // The strain is uniform and exact up to the solver tolerance (1e-10 of EI/L).
    EXPECT_NEAR(solver.state().strain[i](1) / kappa, 1.0, 1e-9) << i;
  }
  EXPECT_GT(solver.state().tip_position_W().x(), 0.5 * radius);  // towards the tendon
}

// The same tendon curling the rod through 6 turns (κ L = 12π): on 11 nodes each segment turns
// 3.8 rad, past RK4's limit of 2.8 on a rotation. The shot runs away (|R(3.8i)|¹⁰ ≈ 3e7), yet the
// residuals vanish (the tendon's pull is internal, a free tip carries nothing), so the solver
// must look at the state: non_finite, in statics, in a dynamics start (which then has nothing
// to step from) and in a step (not taken). On 401 nodes (κh = 0.094 rad a segment) it
// converges on the circle: RK4 shrinks a rotation by about (κh)⁶/144 = 4.9e-9 a step, 1.9e-6
// of the radius over 400 steps (measured 1.9e-6 at the tip); 1e-5 leaves that margin and
// catches any other error.
TEST(Tendons, ARodCurledBeyondItsGridIsNonFiniteNotConverged) {
  TendonRod rod;
  const double offset = 0.005;
  const RodModel model = rod.Model({{"t0", TendonRoute::Parallel(Vec2(offset, 0))}}, 1e6);
  const double tau = truth::TendonTensionForTurn(12 * kPi, rod.EI(), rod.length, offset);
  StaticShootingSolver coarse(model, 11, {}, Tensions({tau}));
  EXPECT_EQ(coarse.Solve(lie::SE3{}, StaticLoads{}).status, SolveStatus::kNonFinite);
  EXPECT_TRUE(coarse.state().RanAway());
  Bdf2ShootingStepper stepper(model, 11);
  StepInput input;
  input.actuation = Tensions({tau});
  EXPECT_EQ(stepper.InitializeAtRest(input).status, SolveStatus::kNonFinite);
  EXPECT_EQ(stepper.Step(input).status, SolveStatus::kNotRun);
  // Started at a quarter turn, then pulled to the 6 turns in one step: the step fails
  // (non_finite) and the run keeps its last converged (sub-)step, which did not run away.
  StepInput gentle;
  gentle.actuation =
      Tensions({truth::TendonTensionForTurn(0.5 * kPi, rod.EI(), rod.length, offset)});
  ASSERT_TRUE(stepper.InitializeAtRest(gentle).converged());
  EXPECT_EQ(stepper.Step(input).status, SolveStatus::kNonFinite);
  EXPECT_LT(stepper.time(), stepper.options().dt);
  EXPECT_FALSE(stepper.state().RanAway());
  EXPECT_LT(stepper.state().tip_position_W().norm(), rod.length);
  StaticShootingSolver fine(model, 401, {}, Tensions({tau}));
  ASSERT_TRUE(fine.Solve(lie::SE3{}, StaticLoads{}).converged());
  const double radius = truth::TendonArcRadius(tau, offset, rod.EI(), rod.EA() * 1e6);
  for (const Vec3& p : fine.state().position_W)
    EXPECT_NEAR((p - Vec3(radius, 0, 0)).norm() / radius, 1.0, 1e-5);
}

// The twist of the tip about its own axis, from the torsion along the rod (rad).
double TipTwist(const RodState& state) {
  double twist = 0;
  for (int i = 0; i + 1 < state.size(); ++i)
    twist += 0.5 * (state.s[i + 1] - state.s[i]) * (state.strain[i](2) + state.strain[i + 1](2));
  return twist;
}

TEST(Tendons, HelicalTendonTwistsAgainstItsHandednessAndMoreWithTension) {
  // Rucker & Webster: a helical tendon's tangent has a hoop part r' besides e3, so its pull on
  // the guides is a torque −τ r × r'/|q| = −τ ρ² w e3/|q| (w = 2π/pitch): the rod twists opposite
  // to the helix, by θ ≈ −τ ρ² w L /(GJ sqrt(1 + ρ² w²)) for small τ, growing monotonically.
  TendonRod rod;
  const double rho = 0.005, pitch = rod.length / 2;  // two full turns: the bending parts cancel
  for (double sign : {1.0, -1.0}) {
    const RodModel model = rod.Model({{"helix", TendonRoute::Helical(rho, sign * pitch, 0.0)}});
    StaticShootingSolver solver(model, 81);
    double last = 0;
    for (double tau : {0.05, 0.5, 2.0, 5.0}) {
      solver.SetActuation(Tensions({tau}));
      const auto summary = solver.Solve(lie::SE3{}, StaticLoads{});
      ASSERT_TRUE(summary.converged()) << tau;
      const double twist = TipTwist(solver.state());
      EXPECT_LT(sign * twist, 0.0) << "tau " << tau;                // against the helix
      EXPECT_GT(std::abs(twist), std::abs(last)) << "tau " << tau;  // grows with tension
      last = twist;
      if (tau == 0.05) {
        const double linear =
            truth::HelicalTendonTwist(tau, rho, sign * pitch, rod.length, rod.GJ());
        // Small tension: the linear prediction to O(τ) relative (τ ρ/EI·L ≈ 2e-3 here) plus the
        // trapezoid rule on the node torsion (h = L/80).
        EXPECT_NEAR(twist / linear, 1.0, 1e-2);
      }
    }
  }
}

TEST(Tendons, BaseReactionBalancesTheExternalLoadsWhateverTheTension) {
  TendonRod rod;
  const RodModel model =
      rod.Model({{"a", TendonRoute::Parallel(Vec2(0.004, 0))},
                 {"b", TendonRoute::Converging(Vec2(0, 0.004), Vec2(0, 0.002))}});
  StaticLoads loads;
  loads.gravity_W = Vec3(0, -9.81, 0);
  loads.tip_force = Vec3(0.2, 0, -0.1);
  StaticShootingSolver solver(model, 41);
  const double mass = 8000 * rod.section().area * rod.length;
  const Vec3 external = mass * loads.gravity_W + loads.tip_force;
  for (double tau : {0.0, 1.0, 5.0, 20.0}) {
    solver.SetActuation(Tensions({tau, 0.5 * tau}));
    ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged()) << tau;
    const Vec6 reaction = solver.state().BaseReaction_W();
    // The support's force cancels gravity and the tip load; tension is internal. 1e-9 relative:
    // the solver tolerance (1e-10 of EI/L²) and the RK4 error of the body-frame force balance.
    EXPECT_LT((reaction.tail<3>() + external).norm(), 1e-9 * external.norm()) << tau;
  }
}

// The three-tendon robot (robots/tendon_three_tendon.json: a 0.8 mm spring-steel backbone, a
// helical tendon 8 mm out) pulled on its helical tendon alone up to τ ρ²/EI = 0.6, where the
// tendon's stiffness ∂T/∂ξ is tens of percent of the backbone's: the strain law must still be
// solved at every stage (it was not from τ ρ²/EI ≈ 0.3, 20 N, and the solve ended non-finite).
// Tension is internal, so the support carries the rod's weight: to the solver's tolerance (1e-9
// relative, as above) and RK4's error in the force balance of sections turning by h κ per step,
// O((h κ)⁴) (measured 0.03–0.045 (h κ)⁴ at h κ = 0.12 … 0.47; bounded by 0.1 (h κ)⁴).
TEST(Tendons, AHelicalTendonPulledHardStillBalancesTheWeight) {
  const io::Problem p = ThreeTendonRobot();
  ASSERT_TRUE(p.rod.section);
  StaticShootingSolver solver(p.rod, p.nodes);
  const double mass = p.rod.section->At(0.0, Actuation{}).mass(5, 5) * p.rod.length;
  const Vec3 weight = mass * p.loads.gravity_W;
  for (double tau : {10.0, 20.0, 30.0, 40.0}) {
    solver.SetActuation(Tensions({0.0, 0.0, tau}));
    const StaticShootingSummary s = solver.Solve(p.base, p.loads);
    ASSERT_TRUE(s.converged()) << tau << " N: " << ToString(s.status);
    const Vec6 reaction = solver.state().BaseReaction_W();
    double kappa = 0.0;
    for (const Vec6& xi : solver.state().strain) kappa = std::max(kappa, xi.head<2>().norm());
    const double h = p.rod.length / (p.nodes - 1);
    const double error = (reaction.tail<3>() + weight).norm() / weight.norm();
    std::printf("%g N: kappa %.3g /m, h kappa %.3g, |reaction + weight| / |weight| %.3g\n", tau,
                kappa, h * kappa, error);
    EXPECT_LT(error, 1e-9 + 0.1 * std::pow(h * kappa, 4)) << tau;
  }
}

TEST(Tendons, TipJacobianInTheTensionsMatchesFiniteDifferences) {
  TendonRod rod;
  const RodModel model = rod.Model({{"a", TendonRoute::Parallel(Vec2(0.004, 0))},
                                    {"b", TendonRoute::Converging(Vec2(0, 0.004), Vec2(0, 0.002))},
                                    {"c", TendonRoute::Helical(0.003, 0.2, 0.3)}});
  StaticLoads loads;
  loads.gravity_W = Vec3(0, -9.81, 0);
  loads.tip_force = Vec3(0.1, 0, -0.05);
  StaticShootingOptions tight;
  tight.tolerance = 1e-13;  // so the differences below are not solver noise
  StaticShootingSolver solver(model, 41, tight);
  const Actuation at = Tensions({2.0, 1.0, 0.5});
  solver.SetActuation(at);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  StaticShootingSolver::TensionJacobian J;
  ASSERT_TRUE(solver.TipJacobianWrtTensions(lie::SE3{}, loads, &J));
  const Mat3 R0 = solver.state().tip_rotation_WB();
  // Only the last solve's equilibrium has these tangents: other loads, or no J, are refused.
  StaticLoads other = loads;
  other.tip_force.x() += 0.01;
  EXPECT_THROW(solver.TipJacobianWrtTensions(lie::SE3{}, other, &J), std::invalid_argument);
  EXPECT_THROW(solver.TipJacobianWrtTensions(lie::SE3{}, loads, nullptr), std::invalid_argument);
  ASSERT_TRUE(solver.TipJacobianWrtTensions(lie::SE3{}, loads, &J));

  // Central differences with δ = 1e-4 N: truncation ~δ² ≈ 1e-8 relative, solver noise at
  // 1e-13 ~1e-9 relative; the Jacobian is exact for the discrete model, so 1e-6 is safe.
  const double delta = 1e-4;
  StaticShootingSolver::TensionJacobian fd = StaticShootingSolver::TensionJacobian::Zero();
  for (int i = 0; i < 3; ++i) {
    Vec3 p[2];
    Vec3 theta[2];
    for (int k = 0; k < 2; ++k) {
      Actuation a = at;
      a.tendon_tension[i] += (k == 0 ? delta : -delta);
      solver.SetActuation(a);
      ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
      p[k] = solver.state().tip_position_W();
      theta[k] = lie::SO3Log(R0.transpose() * solver.state().tip_rotation_WB());
    }
    fd.col(i) << (p[0] - p[1]) / (2 * delta), (theta[0] - theta[1]) / (2 * delta);
  }
  EXPECT_LT((J - fd).norm(), 1e-6 * fd.norm()) << "analytic\n" << J << "\nfd\n" << fd;
  EXPECT_GT(fd.norm(), 1e-3);              // the tensions do move the tip
  EXPECT_TRUE(J.rightCols<5>().isZero());  // no tendons there
}

TEST(Tendons, LengthCommandReachesTheTensionThatProducesItAndASlackTendonCarriesNothing) {
  TendonRod rod;
  const RodModel model = rod.Model({{"a", TendonRoute::Parallel(Vec2(0.004, 0))},
                                    {"b", TendonRoute::Parallel(Vec2(-0.004, 0))}});
  StaticLoads loads;
  loads.gravity_W = Vec3(0, -9.81, 0);
  StaticShootingSolver solver(model, 41);
  // The truth: the lengths that tensions (3 N, 0) produce.
  solver.SetActuation(Tensions({3.0, 0.0}));
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  std::array<double, Actuation::kMaxTendons> command{};
  command[0] = solver.tendon_lengths()[0];
  // Tendon b, opposite, is stretched by the bend; command it 1 mm longer still: it must go slack
  // rather than push.
  command[1] = solver.tendon_lengths()[1] + 1e-3;
  Actuation a = Tensions({0.5, 2.0});  // start elsewhere
  const TendonLengthSummary s = SolveTendonLengths(solver, lie::SE3{}, loads, command, &a);
  ASSERT_TRUE(s.converged()) << ToString(s.status);
  // Length tolerance 1e-10 L; the length-tension slope here is ~1e-4 m/N, so the tension is
  // recovered to ~1e-7 relative.
  EXPECT_NEAR(a.tendon_tension[0], 3.0, 1e-6);
  EXPECT_EQ(a.tendon_tension[1], 0.0);
  EXPECT_TRUE(s.slack[1]);
  EXPECT_FALSE(s.slack[0]);
  EXPECT_NEAR(solver.tendon_lengths()[0], command[0], 1e-10 * rod.length);
  EXPECT_GT(command[1], solver.tendon_lengths()[1]);  // slack: the path is shorter than the cable
}

// n parallel tendons "a", "b", ... at `offset` (m) from the axis, evenly spaced in angle from +x.
void AddEvenlySpacedParallelTendons(int n, double offset, RodModel* model) {
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * kPi * i / n;
    const Vec2 at = offset * Vec2(std::cos(angle), std::sin(angle));
    model->tendons.push_back({std::string(1, char('a' + i)), TendonRoute::Parallel(at)});
  }
}

// Four parallel tendons at 90° make only three strains, two curvatures and the stretch, so
// Newton's matrix on their tensions is singular whenever all four are taut, as they are from
// 0.3 N each. A command reachable with tensions (1.2, 0.5, 0, 0) N and tendon c's cable 2 mm
// longer than its path is reached from there: c slack, the taut tendons' lengths to the 1e-10 L
// asked; and where the tensions are not unique (a pretensioned command, (1.2, 0.5, 0.1, 0.1) N)
// the lengths all the same.
TEST(Tendons, RedundantTendonsReachALengthCommandFromAnyStart) {
  // A nitinol backbone (0.25 m, r 0.6 mm), upright, the tendons 6 mm out.
  const double length = 0.25;
  RodModel model = RodModel::Uniform(length, CrossSection::Circle(0.0006),
                                     Material::FromShearModulus(58e9, 21.8e9, 6450));
  AddEvenlySpacedParallelTendons(4, 0.006, &model);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  StaticShootingSolver solver(model, 41);
  auto command_of = [&](std::initializer_list<double> tau) {
    solver.SetActuation(Tensions(tau));
    EXPECT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
    return solver.tendon_lengths();
  };
  using Lengths = std::array<double, Actuation::kMaxTendons>;
  Lengths slack_c = command_of({1.2, 0.5, 0.0, 0.0});
  slack_c[2] += 2e-3;
  const Lengths pretensioned = command_of({1.2, 0.5, 0.1, 0.1});
  // Pretensioned enough that the family, (1.5, 0.9, 0.6, 0.6) + t (1, −1, 1, −1) for t in
  // [−0.6, 0.6], holds every start's least-norm answer with all four taut.
  const Lengths co_contracted = command_of({1.5, 0.9, 0.6, 0.6});
  const Lengths* commands[] = {&slack_c, &pretensioned, &co_contracted};
  for (const Lengths* c : commands) {
    const auto& command = *c;
    Actuation a = Tensions({0.3, 0.3, 0.3, 0.3});
    const TendonLengthSummary s = SolveTendonLengths(solver, lie::SE3{}, loads, command, &a);
    ASSERT_TRUE(s.converged()) << ToString(s.status) << ", length error " << s.length_error;
    EXPECT_LT(s.length_error, 1e-10 * length);
    int taut = 0;
    for (int i = 0; i < 4; ++i) {
      EXPECT_GE(a.tendon_tension[i], 0.0);
      if (!s.slack[i]) EXPECT_NEAR(solver.tendon_lengths()[i], command[i], 1e-10 * length);
      taut += !s.slack[i];
    }
    // Any three of the four make the three strains independently, so the tensions are free in
    // one direction, (1, −1, 1, −1), exactly when all four are taut, as the summary says.
    EXPECT_EQ(s.free_tension_directions, std::max(0, taut - 3)) << taut << " taut";
    if (c == &co_contracted) EXPECT_EQ(taut, 4);
    if (c != &slack_c) continue;
    // With c slack the other three tensions are unique (three strains): the truth's, to the
    // ~1e-7 N the length tolerance recovers.
    EXPECT_TRUE(s.slack[2]);
    EXPECT_EQ(a.tendon_tension[2], 0.0);
    EXPECT_NEAR(a.tendon_tension[0], 1.2, 1e-6);
    EXPECT_NEAR(a.tendon_tension[1], 0.5, 1e-6);
    EXPECT_NEAR(a.tendon_tension[3], 0.0, 1e-6);
  }
}

// A stiff backbone (steel, r 1.5 mm, 0.25 m) with three parallel tendons 120° apart, 8 mm out:
// the lengths' sensitivity to a common tension is the stretch, about 3 L/EA = 5e-7 m/N, against
// the bends' r² L/EI = 1.9e-5 m/N. Any rank threshold must be relative to these: an absolute one
// of 1e-6 m/N took the stretch for round-off, dropped it from every Newton step and stopped at
// max_iterations with all three tensions 4.7 N low. The three tendons make the three strains,
// so (20, 10, 5) N are the only tensions with their lengths. The length tolerance, 1e-10 L =
// 2.5e-11 m, bounds the common tension's error by 2.5e-11 / 5e-7 = 5e-5 N: 1e-4 asserted.
TEST(Tendons, AStiffBackbonesStretchIsNotTakenForRoundOff) {
  const double length = 0.25;
  RodModel model = RodModel::Uniform(length, CrossSection::Circle(0.0015),
                                     Material::FromShearModulus(210e9, 80e9, 7800));
  AddEvenlySpacedParallelTendons(3, 0.008, &model);
  StaticShootingSolver solver(model, 41);
  solver.SetActuation(Tensions({20.0, 10.0, 5.0}));
  ASSERT_TRUE(solver.Solve(lie::SE3{}, StaticLoads{}).converged());
  std::array<double, Actuation::kMaxTendons> command{};
  for (int i = 0; i < 3; ++i) command[i] = solver.tendon_lengths()[i];
  StaticShootingSolver fresh(model, 41);
  Actuation a;  // from zero tension
  const TendonLengthSummary s = SolveTendonLengths(fresh, lie::SE3{}, StaticLoads{}, command, &a);
  ASSERT_TRUE(s.converged()) << ToString(s.status) << ", length error " << s.length_error;
  EXPECT_NEAR(a.tendon_tension[0], 20.0, 1e-4);
  EXPECT_NEAR(a.tendon_tension[1], 10.0, 1e-4);
  EXPECT_NEAR(a.tendon_tension[2], 5.0, 1e-4);
  EXPECT_EQ(s.free_tension_directions, 0);
}

// Displacement control far from its start: the three-tendon robot's path lengths at (25, 0, 1.5) N
// (a 0.8 mm backbone bent to κ ≈ 47 /m) commanded from zero tension. The search must reach the
// tensions that produce them (tendon b, stretched by the bend, goes slack when commanded at its
// own path's length plus 1 mm), its trial steps halving where a static solve fails. Lengths to
// 1e-10 L; the slope dℓ/dτ ≈ 2e-3 m/N recovers the tensions to ~1e-8 N, 1e-6 asserted.
TEST(Tendons, ALengthCommandFarFromTheStartIsReached) {
  const io::Problem p = ThreeTendonRobot();
  ASSERT_TRUE(p.rod.section);
  StaticShootingSolver solver(p.rod, p.nodes);
  solver.SetActuation(Tensions({25.0, 0.0, 1.5}));
  ASSERT_TRUE(solver.Solve(p.base, p.loads).converged());
  std::array<double, Actuation::kMaxTendons> command{};
  for (int i = 0; i < 3; ++i) command[i] = solver.tendon_lengths()[i];
  command[1] += 1e-3;
  StaticShootingSolver fresh(p.rod, p.nodes);
  Actuation a;  // from zero tension
  const TendonLengthSummary s = SolveTendonLengths(fresh, p.base, p.loads, command, &a);
  ASSERT_TRUE(s.converged()) << ToString(s.status);
  EXPECT_NEAR(a.tendon_tension[0], 25.0, 1e-6);
  EXPECT_EQ(a.tendon_tension[1], 0.0);
  EXPECT_NEAR(a.tendon_tension[2], 1.5, 1e-6);
  EXPECT_TRUE(s.slack[1]);
  EXPECT_LT(s.length_error, 1e-10 * p.rod.length);
  EXPECT_LT(s.residual, 1e-9);  // the final equilibrium's, reported
  EXPECT_EQ(s.free_tension_directions, 0);  // two tendons 120° apart: two independent bends
}

// A two-segment robot: tendon A anchored at the middle (s = L/2, its segment's end), tendon B
// at the tip, passing through the first segment. With A pulled and B slack and no external load,
// the first half is the one-segment robot of length L/2 with A anchored at its tip (the same
// grid, h = L/40), and the second half carries no wrench (W = 0 beyond A's anchor), so it runs on
// straight and unstretched along the first half's end tangent. Both solves converge to 1e-10:
// the tips agree to 1e-9 L. B pulled as well bends the whole rod (its tip moves by κ_B L²/2 ≈ 6e-3 L),
// and the base reaction stays zero (the tensions are internal).
TEST(Tendons, ATendonAnchoredMidRodBendsOnlyItsSegment) {
  TendonRod rod;
  const double L = rod.length;
  Tendon a, b;
  a.route = TendonRoute::Parallel(Vec2(0.008, 0));
  a.anchor = 0.5 * L;
  b.route = TendonRoute::Parallel(Vec2(0, 0.008));
  StaticShootingSolver two(rod.Model({a, b}), 41, {}, Tensions({1.5, 0.0}));
  ASSERT_TRUE(two.Solve(lie::SE3{}, StaticLoads{}).converged());
  TendonRod half;
  half.length = 0.5 * L;
  Tendon a_tip = a;
  a_tip.anchor = 0.0;
  StaticShootingSolver one(half.Model({a_tip}), 21, {}, Tensions({1.5}));
  ASSERT_TRUE(one.Solve(lie::SE3{}, StaticLoads{}).converged());
  const RodState& h = one.state();
  const Vec3 expected = h.tip_position_W() + h.rotation_WB.back().col(2) * (0.5 * L);
  const Vec3 tip = two.state().tip_position_W();
  std::printf("two segments: tip [%.9f, %.9f, %.9f] m, first half + straight [%.9f, %.9f, %.9f] m\n",
              tip.x(), tip.y(), tip.z(), expected.x(), expected.y(), expected.z());
  EXPECT_LT((tip - expected).norm(), 1e-9 * L);
  EXPECT_LT((two.state().position_W[20] - h.tip_position_W()).norm(), 1e-9 * L);

  two.SetActuation(Tensions({1.5, 1.0}));
  ASSERT_TRUE(two.Solve(lie::SE3{}, StaticLoads{}).converged());
  EXPECT_GT((two.state().tip_position_W() - tip).norm(), 5e-3 * L);  // κ_B L²/2 ≈ 6e-3 L
  EXPECT_LT(two.base_wrench_B().norm(), 1e-9);
}

}  // namespace
}  // namespace cosserat
