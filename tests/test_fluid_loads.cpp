// Fluid loads (buoyancy, Morison drag, added mass) against closed forms: Archimedes, the
// cantilever under a uniform load, the Euler–Bernoulli frequencies with the added mass, the
// energy balance of a rod swinging in still water; and the drag's Jacobians against central
// differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/fluid_drag.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/quatfd/radau.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/beam_vibration.hpp"
#include "support/jacobian_check.hpp"
#include "support/modes_of_both_formulations.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using testing::SteelRod;

constexpr double kWater = 1000.0;  // kg/m³

Fluid Water(const Vec3& current = Vec3::Zero(), double cd = 0.0, double ca = 0.0) {
  Fluid f;
  f.density = kWater;
  f.velocity_W = current;
  f.drag_normal = cd;
  f.added_mass = ca;
  return f;
}

// The first bending frequency of a cantilever (Euler–Bernoulli), Hz.
double FirstBendingHz(const SteelRod& rod) {
  return truth::EulerBernoulliOmega(truth::CantileverBetaL(1), rod.EI(), rod.rhoA(), rod.length) /
         (2 * M_PI);
}

// A flow that grows with height as (h / reference_height)^exponent from the given origin.
void SetPowerLawFlow(Fluid* f, double reference_height, double exponent,
                     const Vec3& origin = Vec3::Zero()) {
  f->profile.kind = FluidFlowProfile::Kind::kPowerLaw;
  f->profile.reference_height = reference_height;
  f->profile.exponent = exponent;
  f->profile.origin_W = origin;
}

// --- The drag's own Jacobian -----------------------------------------------------------------

// Central differences at h = 1e-6 (relative to values of order 1): truncation h² |f'''| ≈ 1e-12
// and round-off 1e-16/h ≈ 1e-10 of |f'|, so 1e-7 of the largest entry is a wide margin that any
// wrong term (O(1) of it) still fails.
void ExpectDragJacobianMatchesCentralDifferences(const Fluid& fluid) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const FluidDrag drag(fluid);
  const LoadSite site{0.3, 1.0, 0.6, 0.02};
  for (int trial = 0; trial < 10; ++trial) {
    SectionMotion m;
    m.position_W = Vec3(u(rng), u(rng), 2.0 + u(rng));
    m.tangent_W = Vec3(u(rng), u(rng), u(rng)).normalized();
    m.velocity_W = Vec3(u(rng), u(rng), u(rng));
    MotionJacobian J;
    drag.MotionForce_W(site, m, &J);
    const double h = 1e-6;
    auto check = [&](Vec3 SectionMotion::*field, const Mat3& analytic, const char* name) {
      Mat3 fd;
      for (int k = 0; k < 3; ++k) {
        SectionMotion p = m, q = m;
        (p.*field)(k) += h;
        (q.*field)(k) -= h;
        fd.col(k) =
            (drag.MotionForce_W(site, p, nullptr) - drag.MotionForce_W(site, q, nullptr)) / (2 * h);
      }
      const double scale = std::max(1.0, analytic.cwiseAbs().maxCoeff());
      EXPECT_LT((fd - analytic).cwiseAbs().maxCoeff(), 1e-7 * scale) << name;
    };
    check(&SectionMotion::position_W, J.position, "position");
    check(&SectionMotion::tangent_W, J.tangent, "tangent");
    check(&SectionMotion::velocity_W, J.velocity, "velocity");
  }
}

TEST(FluidDrag, JacobianMatchesCentralDifferencesInAUniformCurrent) {
  Fluid f = Water(Vec3(0.8, -0.3, 0.1), 1.2);
  f.drag_tangential = 0.1;
  ExpectDragJacobianMatchesCentralDifferences(f);
}

TEST(FluidDrag, JacobianMatchesCentralDifferencesInShearedFlows) {
  Fluid f = Water(Vec3(0.8, 0.3, 0.0), 1.2);
  f.drag_tangential = 0.05;
  SetPowerLawFlow(&f, 2.0, 0.14);
  ExpectDragJacobianMatchesCentralDifferences(f);
  f.profile.kind = FluidFlowProfile::Kind::kTable;
  f.profile.points = 3;
  f.profile.height = {0.0, 1.7, 3.5};
  f.profile.factor = {0.2, 0.9, 1.1};
  ExpectDragJacobianMatchesCentralDifferences(f);
}

TEST(FluidDrag, IsMorisonsLawAcrossAndAlongTheRod) {
  Fluid f = Water(Vec3(0.5, 0, 0.2), 1.1);
  f.drag_tangential = 0.02;
  const LoadSite site{0.0, 1.0, 0.0, 0.03};
  SectionMotion m;  // tangent +z, at rest: u_n = 0.5 x, u_t = 0.2 z
  const Vec3 force = FluidDrag(f).MotionForce_W(site, m, nullptr);
  EXPECT_NEAR(force.x(), 0.5 * kWater * 1.1 * 0.03 * 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(force.z(), 0.5 * kWater * 0.02 * M_PI * 0.03 * 0.2 * 0.2, 1e-12);
  EXPECT_EQ(force.y(), 0.0);
}

// --- Buoyancy ----------------------------------------------------------------------------------

// A horizontal cantilever (tangent +x) under gravity −z.
struct HorizontalCantilever {
  SteelRod rod{0.5, 0.004};
  lie::SE3 base;
  HorizontalCantilever() {
    base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // body z along world x
  }
  Vec3 TipSe3(const RodModel& model, const StaticLoads& loads) const {
    StaticShootingSolver solver(model, 41);
    EXPECT_TRUE(solver.Solve(base, loads).converged());
    return solver.state().position_W.back();
  }
};

TEST(Buoyancy, ARodAsDenseAsTheFluidStaysStraight) {
  HorizontalCantilever c;
  c.rod.material.density = kWater;
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  loads.fluid = Water();
  const Vec3 tip = c.TipSe3(c.rod.model(), loads);
  // Weight and buoyancy are ρA g with A = π r² computed two ways (the section's area and
  // π d²/4): they cancel to a few ulp, and the droop of that residue is below 1e-12 L.
  EXPECT_LT(std::abs(tip.z()), 1e-12 * c.rod.length);
  EXPECT_NEAR(tip.x(), c.rod.length, 1e-12);

  // The quaternion-FD model lumps the weight (ρ A Δs/2) and the buoyancy (ρ_f of the displaced
  // volume π d²/4 Δs/2) on each vertex alike: they cancel to round-off there too.
  quatfd::QuatFdOptions options;
  options.segments = 40;
  quatfd::QuatFdModel m(c.rod.model(), c.base, options);
  Eigen::VectorXd q(m.size()), v(m.size());
  m.RestState(q, v);
  ASSERT_TRUE(quatfd::SolveStatics(&m, loads, q).converged());
  const Vec3 tip_fd = q.segment<3>(quatfd::QuatFdLayout::X(options.segments));
  std::printf("as dense as water: SE(3) tip z %.2e m, quatfd tip z %.2e m\n", tip.z(), tip_fd.z());
  EXPECT_LT(std::abs(tip_fd.z()), 1e-12 * c.rod.length);
}

TEST(Buoyancy, ADenseRodDroopsAsADryRodOfTheDensityDifference) {
  HorizontalCantilever c;
  StaticLoads wet;
  wet.gravity_W = Vec3(0, 0, -9.81);
  wet.fluid = Water();
  StaticLoads dry;
  dry.gravity_W = wet.gravity_W;
  SteelRod lighter = c.rod;
  lighter.material.density = c.rod.material.density - kWater;
  const Vec3 tip_wet = c.TipSe3(c.rod.model(), wet);
  const Vec3 tip_dry = c.TipSe3(lighter.model(), dry);
  // The same distributed force (ρ − ρ_f) A g up to rounding: the same equilibrium to 1e-12 L.
  EXPECT_LT((tip_wet - tip_dry).norm(), 1e-12 * c.rod.length);
  EXPECT_GT(-tip_wet.z(), 1e-4 * c.rod.length);  // it does droop

  // The quaternion-FD statics lumps buoyancy per vertex from the displaced volume: the same
  // (to its solver's tolerance, 1e-10 of the residual).
  quatfd::QuatFdOptions options;
  options.segments = 40;
  auto quatfd_tip = [&](const RodModel& model, const StaticLoads& loads) {
    quatfd::QuatFdModel m(model, c.base, options);
    Eigen::VectorXd q(m.size()), v(m.size());
    m.RestState(q, v);
    EXPECT_TRUE(quatfd::SolveStatics(&m, loads, q).converged());
    return Vec3(q.segment<3>(quatfd::QuatFdLayout::X(options.segments)));
  };
  const Vec3 a = quatfd_tip(c.rod.model(), wet), b = quatfd_tip(lighter.model(), dry);
  EXPECT_LT((a - b).norm(), 1e-9 * c.rod.length);
  EXPECT_LT((a - tip_wet).norm(), 1e-3 * c.rod.length);  // and close to the SE(3) answer
}

// --- Drag: small deflection --------------------------------------------------------------------

// A vertical cantilever (tangent +z) across a uniform current along x, no gravity: a uniform
// load q = ½ ρ_f C_dn D U² bends its tip to q L⁴ / (8 EI) (linear beam theory). At δ/L ≈ 1e-3
// the geometric nonlinearity (the current's normal part shrinks as cos θ) and shear are O(1e-3)
// of δ, so 1 % is a safe bound that a wrong coefficient (π, ½, D) still fails.
TEST(FluidDrag, ACantileverAcrossACurrentBendsAsBeamTheory) {
  const SteelRod rod{1.0, 0.005};
  const double U = 0.5, cd = 1.2, D = 2 * rod.r;
  const double q = 0.5 * kWater * cd * D * U * U;
  StaticLoads loads;
  loads.fluid = Water(Vec3(U, 0, 0), cd);
  StaticShootingSolver solver(rod.model(), 41);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  const double expected = q * std::pow(rod.length, 4) / (8 * rod.EI());
  ASSERT_LT(expected, 2e-3 * rod.length);
  const double tip = solver.state().position_W.back().x();
  std::printf("drag: tip %.6e m, q L^4/(8 EI) %.6e m, relative %.2e\n", tip, expected,
              tip / expected - 1);
  EXPECT_NEAR(tip, expected, 0.01 * expected);
  // The stability index is not defined under drag (not a potential load).
  EXPECT_EQ(solver.StabilityIndex(lie::SE3{}, loads, solver.base_wrench_B()), -1);
}

// The static shot's exact Jacobian includes the drag's dependence on the pose: compared with
// central differences of the residual (h = 1e-6 on dimensionless unknowns; the shot's
// amplification keeps the truncation below 1e-7 here).
TEST(FluidDrag, StaticShootingJacobianMatchesFiniteDifferencesUnderAShearedCurrent) {
  const SteelRod rod{0.6, 0.003};
  StaticLoads loads;
  loads.fluid = Water(Vec3(0.4, 0.2, 0), 1.2);
  loads.fluid.drag_tangential = 0.05;
  SetPowerLawFlow(&loads.fluid, 0.5, 0.3, Vec3(0, 0, -0.1));
  loads.gravity_W = Vec3(0, -9.81, 0);
  StaticShootingSolver solver(rod.model(), 21);
  const Vec6 x = (Vec6() << 0.1, -0.2, 0.05, 0.3, -0.1, 0.2).finished();
  Vec6 r;
  const Mat6 J = solver.ResidualJacobian(lie::SE3{}, loads, x, &r);
  testing::ExpectJacobianMatchesCentralDifferences(
      [&](const Vec6& y) { return solver.Residual(lie::SE3{}, loads, y); }, x, J);
}

// The dynamic shot's exact Jacobian with drag (pose, tangent and velocity) and added mass, for
// a moving state, against central differences (tolerance as in test_bdf2_dynamics.cpp).
TEST(FluidDrag, DynamicShootingJacobianMatchesFiniteDifferencesWithDragAndAddedMass) {
  const SteelRod rod{0.5, 0.002};
  Bdf2Options opt;
  Bdf2ShootingStepper stepper(rod.model(), 21, opt);
  StepInput in;
  in.loads.fluid = Water(Vec3(0.3, -0.1, 0.05), 1.2, 1.0);
  in.loads.fluid.drag_tangential = 0.1;
  SetPowerLawFlow(&in.loads.fluid, 0.4, 0.2, Vec3(0, 0, -0.2));
  in.loads.tip_force = Vec3(-0.2, 0.1, 0);
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force = Vec3(0.05, 0, 0.1);
  in.loads.gravity_W = Vec3(0, -9.81, 0);
  in.base_twist_B << 0.1, -0.2, 0.3, 0.01, 0.02, -0.01;
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(stepper.Step(in).converged());
  const double dt = opt.dt;
  const Bdf2ShootingStepper::Coefficients c{1.5 / dt, -2 / dt, 0.5 / dt};
  const Vec6 x = (Vec6() << 0.01, -0.3, 0.02, 0.1, -0.05, 0.2).finished();
  Mat6 J;
  stepper.Residual(in, c, false, x, &J);
  testing::ExpectJacobianMatchesCentralDifferences(
      [&](const Vec6& y) { return stepper.Residual(in, c, false, y); }, x, J);
}

// The same cantilever and current in the quaternion-FD statics at 60 segments (second order in
// the grid: O((h/L)²) ≈ 3e-4 of δ): within 1 % as well. The support carries the whole drag: the
// base reaction is −q L in force and q L²/2 in moment, the clamped vertex's half segment
// included (without it, 0.95 q L at 10 segments, 1/120 short here). The rod turns by
// at most the tip slope q L³/(6 EI) ≈ 2.5e-3 rad, which changes the normal flow and the lever
// arms by O(slope²) ≈ 6e-6 of the load; 1e-4 holds that and fails the missing half segment.
TEST(FluidDrag, QuaternionFdCantileverAcrossACurrentBendsAsBeamTheory) {
  const SteelRod rod{1.0, 0.005};
  const double U = 0.5, cd = 1.2, D = 2 * rod.r;
  const double q_load = 0.5 * kWater * cd * D * U * U;
  StaticLoads loads;
  loads.fluid = Water(Vec3(U, 0, 0), cd);
  quatfd::QuatFdOptions options;
  options.segments = 60;
  quatfd::QuatFdModel model(rod.model(), lie::SE3{}, options);
  Eigen::VectorXd q(model.size()), v(model.size());
  model.RestState(q, v);
  ASSERT_TRUE(quatfd::SolveStatics(&model, loads, q).converged());
  const double tip = q(quatfd::QuatFdLayout::X(options.segments));
  const double expected = q_load * std::pow(rod.length, 4) / (8 * rod.EI());
  std::printf("quatfd drag: tip %.6e m, q L^4/(8 EI) %.6e m, relative %.2e\n", tip, expected,
              tip / expected - 1);
  EXPECT_NEAR(tip, expected, 0.01 * expected);
  RodState state;
  model.ToRodState(q, v, &state);
  const Vec6 reaction = state.BaseReaction_W();  // [moment about the base; force], world
  const double L = rod.length;
  EXPECT_NEAR(reaction[3], -q_load * L, 1e-4 * q_load * L);
  EXPECT_NEAR(reaction[1], -q_load * L * L / 2, 1e-4 * q_load * L * L / 2);
}

// Modes of a cantilever standing in a 1 m/s current (no gravity). The drag depends on the rod's
// tangent, so the bent equilibrium's bending in the flow's plane and across it differ in
// stiffness and the first pair of modes splits (≈ 5.64 / 5.73 Hz against 5.60 Hz in still air).
// Both formulations linearise the drag's pose dependence, each its own way (the SE(3) shot at
// its stages, the quaternion FD at its vertices with the chord's tangent): they agree to their
// grids, measured 6e-4 at 41 nodes; 2e-3 bounds it, and a split missing in either (the SE(3)
// modes without the drag's stiffness have none: 5.603 twice) fails by 1.6 %.
TEST(FluidDrag, BothFormulationsSplitTheModesInACurrentAlike) {
  const SteelRod rod{0.5, 0.001};
  StaticLoads loads;
  loads.fluid = Water(Vec3(1.0, 0, 0), 1.2);
  const testing::ModesOfBothFormulations both = testing::ModesInBothFormulations(rod, loads, 2);
  ASSERT_TRUE(both.se3.converged() && both.quatfd.converged());
  const std::vector<double> a = both.se3.frequencies_hz(), b = both.quatfd.frequencies_hz();
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  std::printf("modes in a current: SE(3) %.5f %.5f Hz, quaternion FD %.5f %.5f Hz\n", a[0], a[1],
              b[0], b[1]);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(a[k], b[k], 2e-3 * b[k]) << k;
  EXPECT_GT(a[1] - a[0], 0.01 * a[0]);  // the split itself
}

// The same rod in the same current, the whole problem turned 90° about the rod's axis (base and
// flow): the drag's damping and its non-symmetric stiffness turn with it, so the damped pair of
// the first mode cannot change. It changed by 4e-4 when taken from the scaled companion matrix
// and by 2.5 % with round-off unscaled; its inverse keeps it to 3e-10. Tolerance 1e-7: the two
// equilibria differ by round-off only (their undamped frequencies agree to 2e-10).
TEST(FluidDrag, TheDampedPairInACurrentDoesNotTurnWithTheProblem) {
  const SteelRod rod{0.5, 0.001};
  auto first_pair = [&](const lie::SE3& base, const Vec3& current) {
    StaticLoads loads;
    loads.fluid = Water(current, 1.2);
    quatfd::QuatFdOptions options;
    options.segments = 40;
    quatfd::QuatFdModel model(rod.model(), base, options);
    model.set_loads(loads);
    ModalOptions mo;
    mo.count = 1;
    const ModalResult r = ComputeModes(&model, loads, mo);
    EXPECT_TRUE(r.converged()) << r.instability;
    EXPECT_EQ(r.damped.size(), 1u);
    return r.damped.empty() ? DampedMode{} : r.damped[0];
  };
  lie::SE3 turned;
  turned.R = lie::SO3Exp(Vec3(0, 0, M_PI / 2));
  const DampedMode a = first_pair(lie::SE3{}, Vec3(1.0, 0, 0)),
                   b = first_pair(turned, Vec3(0, 1.0, 0));
  EXPECT_GT(a.damping_ratio, 0.5);  // the drag damps it heavily (ζ = 0.666)
  EXPECT_NEAR(b.damped_frequency_hz, a.damped_frequency_hz, 1e-7 * a.damped_frequency_hz);
  EXPECT_NEAR(b.damping_ratio, a.damping_ratio, 1e-7 * a.damping_ratio);
}

// Large deflection in a strong current (tip ≈ 0.3 L downstream): the two formulations at 60 grid
// points agree within 0.5 % of L. Their discretisation errors are O(h⁴) (RK4 in s) and O(h²)
// (finite differences, ≈ (1/60)² ≈ 3e-4 of the deflection), and they read the drag's direction
// from the section normal (SE(3)) and from the chord between neighbouring vertices
// (quaternion-FD), which differ by the shear strain, ~1e-6 here.
TEST(FluidDrag, BothFormulationsAgreeInAStrongCurrent) {
  const SteelRod rod{1.0, 0.0015};
  StaticLoads loads;
  loads.fluid = Water(Vec3(1.2, 0, 0), 1.2);
  loads.fluid.drag_tangential = 0.05;
  StaticShootingSolver shooting(rod.model(), 60);
  ASSERT_TRUE(shooting.Solve(lie::SE3{}, loads).converged());
  const Vec3 tip_se3 = shooting.state().position_W.back();
  quatfd::QuatFdOptions options;
  options.segments = 59;  // 60 vertices
  quatfd::QuatFdModel model(rod.model(), lie::SE3{}, options);
  Eigen::VectorXd q(model.size()), v(model.size());
  model.RestState(q, v);
  ASSERT_TRUE(quatfd::SolveStatics(&model, loads, q).converged());
  const Vec3 tip_fd = q.segment<3>(quatfd::QuatFdLayout::X(options.segments));
  std::printf("strong current: SE(3) tip [%.5f, %.5f] m, quatfd tip [%.5f, %.5f] m, %.2e L\n",
              tip_se3.x(), tip_se3.z(), tip_fd.x(), tip_fd.z(),
              (tip_se3 - tip_fd).norm() / rod.length);
  EXPECT_GT(tip_se3.x(), 0.2 * rod.length);  // a large deflection
  EXPECT_LT((tip_se3 - tip_fd).norm(), 0.005 * rod.length);
}

// The quaternion-FD model's banded Jacobian in a fluid, at a moving state, against central
// differences of its acceleration (steps 1e-5 scaled per unknown, as in test_quatfd_model.cpp:
// truncation and round-off both ~1e-10 relative; rows scaled by their largest entry, so 1e-6
// covers both and fails on any missing drag or added-mass term, O(1e-2) of a row).
void ExpectQuatFdVertexRowsMatchCentralDifferences(const Fluid& fluid) {
  // A rubber rod: a steel one's accelerations at a perturbed state are so large that a velocity
  // step changes them below their last digit.
  SteelRod rod{0.5, 0.01};
  rod.material = Material::FromPoissonRatio(5e6, 0.5, 1100);
  quatfd::QuatFdOptions options;
  options.segments = 6;
  quatfd::QuatFdModel model(rod.model(), lie::SE3{}, options);
  StaticLoads loads;
  loads.fluid = fluid;
  loads.gravity_W = Vec3(0, -3.0, -9.81);  // forces at every vertex for the mass to turn
  model.set_loads(loads);
  const int n = model.size();
  Eigen::VectorXd q(n), v(n);
  model.RestState(q, v);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    if (model.IsFixed(i)) continue;  // the clamp
    q(i) += 0.01 * u(rng);
    v(i) += 0.3 * u(rng);
  }
  for (int k = 0; k < options.segments; ++k)  // unit quaternions
    q.segment<4>(quatfd::QuatFdLayout::P(k)).normalize();
  BandedMatrix A, B;
  model.Jacobian(q, v, &A, &B);
  const Eigen::MatrixXd Ad = A.ToDense(), Bd = B.ToDense();
  Eigen::MatrixXd Afd(n, n), Bfd(n, n);
  Eigen::VectorXd ap(n), am(n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd qp = q, qm = q, vp = v, vm = v;
    const double hq = 1e-5 * std::max(1.0, std::abs(q(j)));
    const double hv = 1e-5 * std::max(1.0, std::abs(v(j)));
    qp(j) += hq;
    qm(j) -= hq;
    model.Acceleration(qp, v, ap);
    model.Acceleration(qm, v, am);
    Afd.col(j) = (ap - am) / (2 * hq);
    vp(j) += hv;
    vm(j) -= hv;
    model.Acceleration(q, vp, ap);
    model.Acceleration(q, vm, am);
    Bfd.col(j) = (ap - am) / (2 * hv);
  }
  // The vertex rows (x, where the drag acts); the quaternion rows, which the drag does not
  // touch, carry the stiff rotational accelerations whose round-off in a central difference
  // exceeds this tolerance (test_quatfd_model.cpp checks them against the Jet oracle).
  for (int i = 0; i < n; ++i) {
    if (i % 7 >= 3) continue;
    const double sa = std::max(Afd.row(i).cwiseAbs().maxCoeff(), 1e-12);
    const double sb = std::max(Bfd.row(i).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((Ad.row(i) - Afd.row(i)).cwiseAbs().maxCoeff(), 1e-6 * sa) << "row " << i;
    EXPECT_LT((Bd.row(i) - Bfd.row(i)).cwiseAbs().maxCoeff(), 1e-6 * sb) << "row " << i;
  }
}

// Drag in a sheared flow.
TEST(FluidDrag, QuaternionFdJacobianMatchesCentralDifferences) {
  Fluid f = Water(Vec3(0.8, 0.2, 0), 1.2);
  f.drag_tangential = 0.1;
  SetPowerLawFlow(&f, 0.3, 0.3, Vec3(0, 0, -0.05));
  ExpectQuatFdVertexRowsMatchCentralDifferences(f);
}

// An added mass, alone and with the drag: the vertex mass matrix m I + m_a (I − t tᵀ) turns with
// the chord t between the neighbouring vertices, which the Jacobian must carry.
TEST(AddedMass, QuaternionFdJacobianMatchesCentralDifferences) {
  ExpectQuatFdVertexRowsMatchCentralDifferences(Water(Vec3::Zero(), 0.0, 1.0));
  Fluid f = Water(Vec3(0.8, 0.2, 0), 1.2, 1.0);
  f.drag_tangential = 0.1;
  ExpectQuatFdVertexRowsMatchCentralDifferences(f);
}

// --- Added mass --------------------------------------------------------------------------------

// In still water the bending modes are the dry ones divided by sqrt(1 + C_a ρ_f A_o / (ρ A)):
// the added mass acts on the lateral motion only. The rotary inertia (unchanged) shifts the
// ratio by O((r/L)²) ≈ 1e-4 here, far inside 0.5 %.
TEST(AddedMass, CantileverModesInStillWaterAreTheDryOnesOverTheMassRatio) {
  const SteelRod rod{0.5, 0.004};
  ShootingModalOptions options;
  options.modal.count = 4;  // two planes: each bending mode is a pair
  const ModalResult dry = ComputeModesShooting(rod.model(), 41, lie::SE3{}, StaticLoads{}, options);
  StaticLoads wet;
  wet.fluid = Water(Vec3::Zero(), 0.0, 1.0);
  const ModalResult in_water = ComputeModesShooting(rod.model(), 41, lie::SE3{}, wet, options);
  ASSERT_EQ(dry.modes.size(), 4u);
  ASSERT_EQ(in_water.modes.size(), 4u);
  const double area = M_PI * rod.r * rod.r;
  const double ratio = std::sqrt(1.0 + kWater * area / rod.rhoA());
  for (int k : {0, 2}) {  // the first and second bending modes
    const double expected = dry.modes[k].frequency_hz / ratio;
    std::printf("mode %d: wet %.6f Hz, dry / ratio %.6f Hz\n", k / 2 + 1,
                in_water.modes[k].frequency_hz, expected);
    EXPECT_NEAR(in_water.modes[k].frequency_hz, expected, 0.005 * expected) << "mode " << k / 2 + 1;
  }
  // and the dry ones are the Euler–Bernoulli ones (the reference the ratio divides)
  const double f1 = FirstBendingHz(rod);
  EXPECT_NEAR(dry.modes[0].frequency_hz, f1, 0.005 * f1);
}

// Free vibration of the SE(3) stepper: the period of the first mode grows by the same ratio.
// Periods are measured between upward zero crossings of the tip over 4 cycles, interpolated
// linearly within a step (dt = T/150: the BDF2 period error, O((ω dt)²) ≈ 2e-3, is common to
// both runs and cancels in the ratio to well under the 1 % tolerance).
/// The mean period between the upward zero crossings of a sampled x(t) over four cycles,
/// interpolated linearly within a sample of length dt; `advance` moves on one sample and gives
/// (t, x), or returns false past its time limit.
double PeriodOfUpwardCrossings(double x0, double dt,
                               const std::function<bool(double*, double*)>& advance) {
  std::vector<double> crossings;
  double x_prev = x0, t, x;
  while (crossings.size() < 5 && advance(&t, &x)) {
    if (x_prev < 0 && x >= 0) crossings.push_back(t - dt * x / (x - x_prev));
    x_prev = x;
  }
  EXPECT_EQ(crossings.size(), 5u);
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

double TipPeriod(const StaticLoads& loads) {
  const SteelRod rod{0.5, 0.004};
  const double f1 = FirstBendingHz(rod);
  Bdf2Options opt;
  opt.dt = 1.0 / (150 * f1);
  Bdf2ShootingStepper stepper(rod.model(), 31, opt);
  StepInput in;
  in.loads = loads;
  in.loads.tip_force = Vec3(0.05, 0, 0);
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  return PeriodOfUpwardCrossings(stepper.state().position_W.back().x(), opt.dt,
                                 [&](double* t, double* x) {
                                   if (stepper.time() >= 10.0 / f1) return false;
                                   EXPECT_TRUE(stepper.Step(in).converged());
                                   *t = stepper.time();
                                   *x = stepper.state().position_W.back().x();
                                   return true;
                                 });
}

/// The period measured in still water over the dry one, against sqrt(1 + C_a ρ_f A_o / ρA).
void ExpectPeriodRatioInStillWater(const char* who,
                                   const std::function<double(const StaticLoads&)>& period) {
  const SteelRod rod{0.5, 0.004};
  StaticLoads wet;
  wet.fluid = Water(Vec3::Zero(), 0.0, 1.0);
  const double ratio = std::sqrt(1.0 + kWater * M_PI * rod.r * rod.r / rod.rhoA());
  const double measured = period(wet) / period(StaticLoads{});
  std::printf("%s added mass: period ratio %.6f, expected %.6f\n", who, measured, ratio);
  EXPECT_NEAR(measured, ratio, 0.01 * ratio) << who;
}

TEST(AddedMass, FreeVibrationInStillWaterIsSlowerByTheMassRatio) {
  ExpectPeriodRatioInStillWater("SE(3)", TipPeriod);
}

// The same in the quaternion-FD modes (40 segments): each vertex carries m_a / m = ρ_f A_o / (ρ A)
// of its own mass on its lateral motion, so the ratio is that of the continuum up to the rotary
// inertia's O((r/L)²); the grid's own error (≈ 0.1 % on mode 2) is common to both spectra.
TEST(AddedMass, QuaternionFdModesInStillWaterAreTheDryOnesOverTheMassRatio) {
  const SteelRod rod{0.5, 0.004};
  quatfd::QuatFdOptions grid;
  grid.segments = 40;
  ModalOptions options;
  options.count = 4;
  quatfd::QuatFdModel model(rod.model(), lie::SE3{}, grid);
  const ModalResult dry = ComputeModes(&model, StaticLoads{}, options);
  StaticLoads wet;
  wet.fluid = Water(Vec3::Zero(), 0.0, 1.0);
  const ModalResult in_water = ComputeModes(&model, wet, options);
  ASSERT_EQ(dry.modes.size(), 4u);
  ASSERT_EQ(in_water.modes.size(), 4u);
  const double ratio = std::sqrt(1.0 + kWater * M_PI * rod.r * rod.r / rod.rhoA());
  for (int k : {0, 2}) {
    const double expected = dry.modes[k].frequency_hz / ratio;
    std::printf("quatfd mode %d: wet %.6f Hz, dry / ratio %.6f Hz\n", k / 2 + 1,
                in_water.modes[k].frequency_hz, expected);
    EXPECT_NEAR(in_water.modes[k].frequency_hz, expected, 0.005 * expected) << "mode " << k / 2 + 1;
  }
  const double f1 = FirstBendingHz(rod);  // and the dry one is Euler–Bernoulli's
  EXPECT_NEAR(dry.modes[0].frequency_hz, f1, 0.005 * f1);
}

// Free vibration of the quaternion-FD rod (Radau IIA, 20 segments): the first period grows by the
// same ratio. Zero crossings of the tip over 4 cycles from 1 ms frames, interpolated linearly
// (frame error ~(ω Δt)² / 8 of a crossing's timing, ≈ 1e-3 of a period, common to both runs).
/// The quaternion-FD cantilever of these tests (0.5 m steel, r 4 mm, 20 segments) held by a tip
/// pull (N, along x) under `loads` and let go: the model, its loads set to `loads`, the pulled
/// state at rest, and a Radau IIA integrator at tolerance 1e-8.
struct ReleasedQuatFdCantilever {
  static constexpr int kSegments = 20;
  SteelRod rod{0.5, 0.004};
  quatfd::QuatFdModel model;
  Eigen::VectorXd q, v;
  quatfd::RadauIntegrator radau;
  static quatfd::QuatFdOptions Grid() {
    quatfd::QuatFdOptions grid;
    grid.segments = kSegments;
    return grid;
  }
  static quatfd::IntegratorOptions Tolerance() {
    quatfd::IntegratorOptions io;
    io.rel_tol = io.abs_tol = 1e-8;
    return io;
  }
  ReleasedQuatFdCantilever(const StaticLoads& loads, double pull)
      : model(rod.model(), lie::SE3{}, Grid()),
        q(model.size()),
        v(model.size()),
        radau(model, Tolerance()) {
    StaticLoads pulled = loads;
    pulled.tip_force = Vec3(pull, 0, 0);
    model.RestState(q, v);
    EXPECT_TRUE(quatfd::SolveStatics(&model, pulled, q).converged());
    model.set_loads(loads);
  }
};

double QuatFdTipPeriod(const StaticLoads& loads) {
  ReleasedQuatFdCantilever c(loads, 0.05);
  Eigen::VectorXd &q = c.q, &v = c.v;
  const double frame = 1e-3, f1 = FirstBendingHz(c.rod);
  const int tip = quatfd::QuatFdLayout::X(c.kSegments);
  double t = 0;
  int i = 0;
  return PeriodOfUpwardCrossings(q(tip), frame, [&](double* t_out, double* x) {
    if (t >= 10.0 / f1) return false;
    EXPECT_EQ(c.radau.Advance(++i * frame, &t, q, v), quatfd::IntegratorStatus::kOk);
    *t_out = t;
    *x = q(tip);
    return true;
  });
}

TEST(AddedMass, QuaternionFdFreeVibrationInStillWaterIsSlowerByTheMassRatio) {
  ExpectPeriodRatioInStillWater("quatfd", QuatFdTipPeriod);
}

// The same rods in still water without drag or damping keep their energy once the fluid's share,
// ½ m_a |v_n|² with m_a = C_a ρ_f A_o, is counted with the rod's kinetic energy: left out, the total
// would dip by m_a / (m + m_a) = 11 % of the kinetic energy at each swing through the middle. Over
// three periods the SE(3) run (dt = T/600) keeps it within 1 % (BDF2's numerical damping of the
// released high modes: 0.38 % measured, 0.42 % dry; 2.3 % at T/150), the quaternion-FD run
// (Radau at 1e-8) within 0.1 % (0.07 % measured).
TEST(AddedMass, AnUndampedSwingInStillWaterKeepsTheEnergyOfRodAndFluid) {
  StaticLoads wet;
  wet.fluid = Water(Vec3::Zero(), 0.0, 1.0);
  const SteelRod rod{0.5, 0.004};
  const double f1 = FirstBendingHz(rod);
  Bdf2Options opt;
  opt.dt = 1.0 / (600 * f1);
  Bdf2ShootingStepper stepper(rod.model(), 31, opt);
  StepInput in;
  in.loads = wet;
  in.loads.tip_force = Vec3(0.05, 0, 0);
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  const double e0 = stepper.Energy(wet).total();
  double worst = 0, peak_kinetic = 0;
  while (stepper.time() < 3.0 / f1) {
    ASSERT_TRUE(stepper.Step(in).converged());
    const RodEnergy e = stepper.Energy(wet);
    worst = std::max(worst, std::abs(e.total() / e0 - 1));
    peak_kinetic = std::max(peak_kinetic, e.kinetic);
  }
  std::printf("SE(3) in still water: energy within %.3g of the start's\n", worst);
  EXPECT_GT(peak_kinetic, 0.5 * e0);  // it did swing through the middle
  EXPECT_LT(worst, 1e-2);

  ReleasedQuatFdCantilever c(wet, 0.05);
  const double q0 = c.model.Energy(c.q, c.v).total();
  double t = 0, worst_fd = 0;
  for (int i = 1; t < 3.0 / f1; ++i) {
    ASSERT_EQ(c.radau.Advance(i * 1e-3, &t, c.q, c.v), quatfd::IntegratorStatus::kOk);
    worst_fd = std::max(worst_fd, std::abs(c.model.Energy(c.q, c.v).total() / q0 - 1));
  }
  std::printf("quaternion FD in still water: energy within %.3g of the start's\n", worst_fd);
  EXPECT_LT(worst_fd, 1e-3);
}

// --- Drag damping: the energy balance ------------------------------------------------------------

// A cantilever released in still water with quadratic drag: between two instants the rod's
// energy drops by the work the drag does, ∫∫ f·v ds dt (quadrature of the stepper's stage points
// in s, trapezoid in t). BDF2's own numerical dissipation at dt = T/400 is measured dry (the
// same run without fluid) and must stay below 0.1 of the drag's, so the balance is a check of the
// drag and not of the integrator; 2 % covers the O(dt²) trapezoid and the remaining dissipation.
struct SwingInWater {
  double energy_lost = 0, drag_work = 0;
};
SwingInWater Swing(const Fluid& fluid, int cycles) {
  const SteelRod rod{0.5, 0.004};
  const double f1 = FirstBendingHz(rod);
  Bdf2Options opt;
  opt.dt = 1.0 / (400 * f1);
  Bdf2ShootingStepper stepper(rod.model(), 31, opt);
  StepInput in;
  in.loads.fluid = fluid;
  in.loads.tip_force = Vec3(3.0, 0, 0);  // a large swing: tip ≈ 0.1 L
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  auto drag_power = [&]() {
    double p = 0;
    for (const RodQuadraturePoint& pt : stepper.QuadraturePoints()) {
      const Vec3 v = pt.rotation_WB * pt.twist_B.tail<3>();
      const SectionMotion m{pt.position_W, pt.rotation_WB.col(2), v};
      p += pt.weight * TotalMotionForce_W(in.loads, pt.section->Site(), m, nullptr).dot(v);
    }
    return p;
  };
  EXPECT_TRUE(stepper.Step(in).converged());  // the released state, with its first rates
  SwingInWater out;
  const double e0 = stepper.Energy(in.loads).total();
  double p_prev = drag_power();
  const int steps = static_cast<int>(std::round(cycles * 400));
  for (int i = 0; i < steps; ++i) {
    EXPECT_TRUE(stepper.Step(in).converged());
    const double p = drag_power();
    out.drag_work += 0.5 * (p + p_prev) * opt.dt;
    p_prev = p;
  }
  out.energy_lost = e0 - stepper.Energy(in.loads).total();
  return out;
}

TEST(FluidDrag, ASwingInStillWaterLosesTheEnergyTheDragDissipates) {
  const SwingInWater dry = Swing(Fluid{}, 2);
  const SwingInWater wet = Swing(Water(Vec3::Zero(), 2.0), 2);
  ASSERT_GT(wet.energy_lost, 0.0);
  EXPECT_LT(std::abs(dry.energy_lost), 0.1 * wet.energy_lost);  // the integrator's own share
  std::printf("swing: energy lost %.6e J, drag work %.6e J, dry loss %.3e J\n", wet.energy_lost,
              wet.drag_work, dry.energy_lost);
  // The drag does negative work: energy lost = −∫ P dt.
  EXPECT_NEAR(wet.energy_lost, -wet.drag_work, 0.02 * wet.energy_lost);
}

// The same balance in the quaternion-FD formulation (Radau IIA at tolerance 1e-8, 20 segments):
// the drag's power Σ f_n · ẋ_n over the vertices, 1 ms frames (T/80: the trapezoid's O(Δt²) error
// is ~1e-4 of the work), and the integrator's own dissipation, measured dry, below 0.1 of it.
SwingInWater QuatFdSwing(const Fluid& fluid, int cycles) {
  StaticLoads loads;
  loads.fluid = fluid;
  ReleasedQuatFdCantilever c(loads, 3.0);
  const quatfd::QuatFdModel& model = c.model;
  Eigen::VectorXd &q = c.q, &v = c.v;
  auto drag_power = [&]() {
    double p = 0;
    for (int n = 0; n <= c.kSegments; ++n) {
      const Vec3 x = q.segment<3>(quatfd::QuatFdLayout::X(n));
      const Vec3 xd = v.segment<3>(quatfd::QuatFdLayout::X(n));
      const SectionMotion m{x, model.VertexDirection(q, n), xd};
      p += TotalMotionForce_W(loads, model.VertexSite(n), m, nullptr).dot(xd);
    }
    return p;
  };
  SwingInWater out;
  const double e0 = model.Energy(q, v).total(), frame = 1e-3;
  const int frames = static_cast<int>(std::round(cycles / (FirstBendingHz(c.rod) * frame)));
  double t = 0, p_prev = drag_power();
  for (int i = 1; i <= frames; ++i) {
    EXPECT_EQ(c.radau.Advance(i * frame, &t, q, v), quatfd::IntegratorStatus::kOk);
    const double p = drag_power();
    out.drag_work += 0.5 * (p + p_prev) * frame;
    p_prev = p;
  }
  out.energy_lost = e0 - model.Energy(q, v).total();
  return out;
}

TEST(FluidDrag, AQuaternionFdSwingInStillWaterLosesTheEnergyTheDragDissipates) {
  const SwingInWater dry = QuatFdSwing(Fluid{}, 2);
  const SwingInWater wet = QuatFdSwing(Water(Vec3::Zero(), 2.0), 2);
  ASSERT_GT(wet.energy_lost, 0.0);
  EXPECT_LT(std::abs(dry.energy_lost), 0.1 * wet.energy_lost);
  std::printf("quatfd swing: energy lost %.6e J, drag work %.6e J, dry loss %.3e J\n",
              wet.energy_lost, wet.drag_work, dry.energy_lost);
  EXPECT_NEAR(wet.energy_lost, -wet.drag_work, 0.02 * wet.energy_lost);
}

// --- Bad input ---------------------------------------------------------------------------------

TEST(Fluid, BadValuesAreRefusedNamingTheKey) {
  Fluid f = Water();
  std::string why;
  EXPECT_TRUE(f.IsValid(&why));
  f.drag_normal = -1;
  EXPECT_FALSE(f.IsValid(&why));
  EXPECT_NE(why.find("environment.fluid.drag_normal"), std::string::npos) << why;
  f = Water();
  f.velocity_W.x() = NAN;
  EXPECT_FALSE(f.IsValid(&why));
  EXPECT_NE(why.find("velocity"), std::string::npos) << why;
  f = Water();
  f.profile.kind = FluidFlowProfile::Kind::kTable;
  f.profile.points = 2;
  f.profile.height = {1.0, 0.5};
  EXPECT_FALSE(f.IsValid(&why));
  EXPECT_NE(why.find("heights"), std::string::npos) << why;
}

}  // namespace
}  // namespace cosserat
