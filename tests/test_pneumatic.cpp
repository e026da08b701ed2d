// Rods with pressurised chambers (constitutive/chamber_law.hpp) against the truth: the exact
// circular arc of one chamber, pure extension under two opposed chambers, two arcs from two
// segments, and the follower nature of the actuation (a chamber-bent rod under gravity is exactly
// the rod of the shifted rest strain), on the SE(3) shooting statics and the quaternion-FD
// statics; a controller's change of pressure needs no new solver.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cosserat/constitutive/chamber_law.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/chamber.hpp"

namespace cosserat {
namespace {

using quatfd::QuatFdModel;
using quatfd::QuatFdOptions;
constexpr double kPi = 3.14159265358979323846;

// A soft silicone finger: L = 0.2 m, radius 10 mm, E = 1 MPa, ν = 0.5 (G = E/3), ρ = 1100 kg/m³.
// Chambers of radius 3 mm (A = 2.83e-5 m²) at 5 mm from the axis: |r| + sqrt(A/π) = 8 mm < 10 mm.
struct SiliconeRod {
  double length = 0.2;
  CrossSection section = CrossSection::Circle(0.01);
  Material material = Material::FromShearModulus(1e6, 1e6 / 3, 1100);
  double chamber_area = kPi * 0.003 * 0.003;
  double offset = 0.005;
  double EI() const { return material.youngs_modulus * section.I1; }
  double EA() const { return material.youngs_modulus * section.area; }
  RodModel Model(std::vector<Chamber> chambers) const {
    RodModel m = RodModel::Uniform(length, section, material);
    m.chambers = std::move(chambers);
    return m;
  }
  Chamber At(Vec2 r, double s0, double s1) const { return {"", r, chamber_area, s0, s1}; }
};

Actuation Pressures(std::initializer_list<double> p) {
  Actuation a;
  int i = 0;
  for (double x : p) a.chamber_pressure[i++] = x;
  return a;
}

RodState SolveShooting(const RodModel& model, const Actuation& act, const StaticLoads& loads,
                       int nodes = 41) {
  StaticShootingSolver solver(model, nodes, {}, act);
  const auto summary = solver.Solve(lie::SE3{}, loads);
  EXPECT_TRUE(summary.converged()) << ToString(summary.status);
  return solver.state();
}

// The quaternion-FD static equilibrium, solved from the straight rod (the unactuated rest state),
// so that Newton has to find the arc; `discrete_rest` gets the model's own actuated rest shape.
RodState SolveQuatFd(const RodModel& model, const Actuation& act, const StaticLoads& loads,
                     int segments, RodState* discrete_rest = nullptr) {
  QuatFdOptions opt;
  opt.segments = segments;
  QuatFdModel fd(model, lie::SE3{}, opt, act);
  Eigen::VectorXd q(fd.size()), v(fd.size());
  QuatFdModel(model, lie::SE3{}, opt).RestState(q, v);  // straight: no pressure
  const auto s = quatfd::SolveStatics(&fd, loads, q);
  EXPECT_TRUE(s.converged()) << ToString(s.status) << " residual " << s.residual;
  RodState state;
  fd.ToRodState(q, v, &state);
  if (discrete_rest) {
    fd.RestState(q, v);
    fd.ToRodState(q, v, discrete_rest);
  }
  return state;
}

TEST(Pneumatic, OneChamberBendsTheRodIntoTheClosedFormArcOnBothFormulations) {
  SiliconeRod rod;
  const RodModel model = rod.Model({rod.At(Vec2(rod.offset, 0), 0, rod.length)});
  // A quarter circle, κ L = π/2: p = 4.4e5 Pa, which also stretches the rod by p A / EA = 4 %.
  const double p =
      truth::ChamberPressureForTurn(0.5 * kPi, rod.EI(), rod.length, rod.chamber_area, rod.offset);
  const double k = -truth::ChamberArcCurvature(p, rod.chamber_area, rod.offset, rod.EI());
  const double nu = truth::ChamberStretch(p * rod.chamber_area, rod.EA());
  const truth::ArcPose tip = truth::BodyYArc(k, nu, rod.length);
  ASSERT_LT(tip.p.x(), -0.5 * nu / std::abs(k));  // bent away from the chamber (+x)

  // SE(3) shooting: the strain is exactly uniform (W = 0), and RK4 at h = L/40 integrates the
  // arc with a local error ~(κh)^5/120 of the radius per step (κh = π/80, radius 0.66 L): 40
  // steps give ~2e-8 L at the tip (measured 2.1e-8 L), 50 times inside 1e-6 L.
  const RodState se3 = SolveShooting(model, Pressures({p}), StaticLoads{});
  const double e_se3 = (se3.tip_position_W() - tip.p).norm() / rod.length;
  EXPECT_LT(e_se3, 1e-6);
  EXPECT_LT((se3.tip_rotation_WB() - tip.R).norm(), 1e-6);
  for (const Vec6& xi : se3.strain) {
    EXPECT_NEAR(xi(1) / k, 1.0, 1e-9);
    EXPECT_NEAR(xi(5), nu, 1e-9);
  }
  std::printf("SE(3) tip error %.3g L\n", e_se3);

  // Quaternion FD: the discrete equilibrium is the discrete arc of constant curvature K* (the
  // model's actuated rest shape) to the solver tolerance, solved from the straight rod. That arc
  // differs from the continuum one at O(h²): variant-1 curvature (4/h) tan(θ/4) = κ turns each
  // segment by θ = κh − κ³h³/48 + ..., and the clamp's half element by its own O(h³); the tip
  // error is measured at 40 and 80 segments, its order asserted, and the Richardson extrapolation
  // (4 e80 − e40)/3, whose error is O(h⁴), must meet 1e-6 L.
  Vec3 tips[2];
  double errors[2];
  for (int level = 0; level < 2; ++level) {
    RodState discrete;
    const RodState fd = SolveQuatFd(model, Pressures({p}), StaticLoads{}, 40 << level, &discrete);
    EXPECT_LT((fd.tip_position_W() - discrete.tip_position_W()).norm(), 1e-9 * rod.length);
    tips[level] = fd.tip_position_W();
    errors[level] = (tips[level] - tip.p).norm() / rod.length;
  }
  const double order = std::log2(errors[0] / errors[1]);
  const double e_richardson = ((4 * tips[1] - tips[0]) / 3 - tip.p).norm() / rod.length;
  std::printf("quaternion-FD tip error %.3g L (40), %.3g L (80), order %.3f, Richardson %.3g L\n",
              errors[0], errors[1], order, e_richardson);
  EXPECT_NEAR(order, 2.0, 0.1);
  EXPECT_LT(e_richardson, 1e-6);
}

TEST(Pneumatic, TwoOpposedChambersAtEqualPressureOnlyExtendTheRod) {
  SiliconeRod rod;
  const RodModel model = rod.Model(
      {rod.At(Vec2(rod.offset, 0), 0, rod.length), rod.At(Vec2(-rod.offset, 0), 0, rod.length)});
  const double p = 2e5;  // Pa: stretch 2 p A / EA = 3.6 %
  const double stretch = 2 * p * rod.chamber_area / rod.EA();
  // The two moments cancel exactly in floating point (p A d − p A d), so the rod stays straight
  // to round-off, and Γ3 = 1 + 2pA/EA is exact in the law; the tip sits at (1 + stretch) L.
  const RodState se3 = SolveShooting(model, Pressures({p, p}), StaticLoads{});
  const RodState fd = SolveQuatFd(model, Pressures({p, p}), StaticLoads{}, 40);
  for (const RodState* s : {&se3, &fd}) {
    EXPECT_LT(s->tip_position_W().head<2>().norm(), 1e-12 * rod.length);
    EXPECT_NEAR(s->tip_position_W().z() / rod.length, 1 + stretch, 1e-12);
  }
  std::printf("extension %.6g (exact %.6g), lateral %.3g L\n",
              se3.tip_position_W().z() / rod.length - 1, stretch,
              se3.tip_position_W().head<2>().norm() / rod.length);
}

TEST(Pneumatic, TwoSegmentsGiveTwoArcsOfTheirOwnCurvature) {
  // Chamber 0 at +x on [0, 0.12) m, chamber 1 at −x on [0.12, 0.2] m at another pressure: an S
  // whose two arcs are the closed form's, joined with continuous tangent (the chamber end becomes
  // a grid node, so no integration step straddles the jump).
  SiliconeRod rod;
  const double s1 = 0.12;
  const RodModel model =
      rod.Model({rod.At(Vec2(rod.offset, 0), 0, s1), rod.At(Vec2(-rod.offset, 0), s1, rod.length)});
  const double p0 = 3e5, p1 = 1.5e5;
  const double k0 = -truth::ChamberArcCurvature(p0, rod.chamber_area, rod.offset, rod.EI());
  const double k1 = truth::ChamberArcCurvature(p1, rod.chamber_area, rod.offset, rod.EI());
  const double nu0 = truth::ChamberStretch(p0 * rod.chamber_area, rod.EA());
  const double nu1 = truth::ChamberStretch(p1 * rod.chamber_area, rod.EA());
  const truth::ArcPose a = truth::BodyYArc(k0, nu0, s1);
  const truth::ArcPose b = truth::BodyYArc(k1, nu1, rod.length - s1);
  const Vec3 tip = a.p + a.R * b.p;

  const RodState se3 = SolveShooting(model, Pressures({p0, p1}), StaticLoads{});
  for (size_t i = 0; i < se3.s.size(); ++i)
    EXPECT_NEAR(se3.strain[i](1), se3.s[i] < s1 ? k0 : k1, 1e-9 * std::abs(k0)) << se3.s[i];
  // RK4 as in the one-chamber arc: measured 3e-9 L.
  const double e_se3 = (se3.tip_position_W() - tip).norm() / rod.length;
  EXPECT_LT(e_se3, 1e-6);
  // Quaternion FD at 80 segments: O(h²) as above, 5.8e-6 L measured; 1e-4 L bounds it.
  const RodState fd = SolveQuatFd(model, Pressures({p0, p1}), StaticLoads{}, 80);
  const double e_fd = (fd.tip_position_W() - tip).norm() / rod.length;
  EXPECT_LT(e_fd, 1e-4);
  std::printf("two segments: SE(3) tip error %.3g L, quaternion FD (80) %.3g L\n", e_se3, e_fd);
}

TEST(Pneumatic, ActuationFollowsTheRodExactlyLikeARestStrain) {
  // Under gravity across the rod, the chamber-bent rod must be exactly the rod with the rest
  // strain ξ* = [κ, 0, 0, 0, 0, Γ3] (the law is W = K(ξ − ξ*) − w, w constant in the body frame).
  // A dead-load actuation (w as a world-frame tip wrench) misses it by far: checked below.
  SiliconeRod rod;
  const RodModel chambered = rod.Model({rod.At(Vec2(0, rod.offset), 0, rod.length)});
  const double p = 2e5;
  // r = (0, d): r × e3 = (d, 0, 0), so κ1 = +p A d / EI: bent towards −y.
  Vec6 rest = StraightRestStrain();
  rest(0) = truth::ChamberArcCurvature(p, rod.chamber_area, rod.offset, rod.EI());
  rest(5) = truth::ChamberStretch(p * rod.chamber_area, rod.EA());
  RodModel curved = rod.Model({});
  curved.rest_strain = [rest](double) { return rest; };
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);

  // SE(3): the same ODE sample by sample, so the shapes agree to the solver tolerance (1e-10 of
  // the dimensionless residual); 1e-9 L.
  const RodState a = SolveShooting(chambered, Pressures({p}), loads);
  const RodState b = SolveShooting(curved, Actuation{}, loads);
  double worst = 0;
  for (size_t i = 0; i < a.s.size(); ++i)
    worst = std::max(worst, (a.position_W[i] - b.position_W[i]).norm() / rod.length);
  EXPECT_LT(worst, 1e-9);
  // Quaternion FD: the same discrete model, so the same tolerance.
  const RodState c = SolveQuatFd(chambered, Pressures({p}), loads, 40);
  const RodState d = SolveQuatFd(curved, Actuation{}, loads, 40);
  double worst_fd = 0;
  for (size_t i = 0; i < c.s.size(); ++i)
    worst_fd = std::max(worst_fd, (c.position_W[i] - d.position_W[i]).norm() / rod.length);
  EXPECT_LT(worst_fd, 1e-9);
  // And the load matters: the shape is not the weightless arc.
  const RodState e = SolveShooting(chambered, Pressures({p}), StaticLoads{});
  EXPECT_GT((a.tip_position_W() - e.tip_position_W()).norm(), 1e-3 * rod.length);
  // The same actuation wrench as a dead load, a world-frame tip moment and force (the body frame
  // at the base is the world's), is another rod altogether: its axial force bends a curved rod.
  StaticLoads dead = loads;
  const Vec6 w = ChamberWrench(chambered.chambers, 0.0, Pressures({p}));
  dead.tip_moment = w.head<3>();
  dead.tip_force = w.tail<3>();
  const RodState f = SolveShooting(rod.Model({}), Actuation{}, dead);
  const double dead_error = (f.tip_position_W() - a.tip_position_W()).norm() / rod.length;
  EXPECT_GT(dead_error, 1e-2);
  std::printf(
      "chambers vs rest strain under gravity: SE(3) %.3g L, quaternion FD %.3g L; "
      "as a dead load: %.3g L\n",
      worst, worst_fd, dead_error);
}

TEST(Pneumatic, ControllerChangesThePressureWithoutANewSolver) {
  SiliconeRod rod;
  const RodModel model = rod.Model({rod.At(Vec2(rod.offset, 0), 0, rod.length)});
  StaticShootingSolver solver(model, 41);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, StaticLoads{}).converged());
  EXPECT_LT(solver.state().tip_position_W().head<2>().norm(), 1e-12);  // no pressure: straight
  for (double p : {1e5, 3e5, 2e5}) {
    solver.SetActuation(Pressures({p}));
    ASSERT_TRUE(solver.Solve(lie::SE3{}, StaticLoads{}).converged());
    const double k = -truth::ChamberArcCurvature(p, rod.chamber_area, rod.offset, rod.EI());
    const double nu = truth::ChamberStretch(p * rod.chamber_area, rod.EA());
    EXPECT_LT((solver.state().tip_position_W() - truth::BodyYArc(k, nu, rod.length).p).norm(),
              1e-6 * rod.length)
        << p;
  }
}

TEST(Pneumatic, DynamicsFollowsAPressureRampToTheArc) {
  // BDF2 dynamics, the pressure ramped by the step input from 0 to the quarter-circle pressure
  // over 0.5 s and then held. Kelvin–Voigt damping of retardation time τ = 0.2 s makes the first
  // bending mode (ω1 = 3.516 sqrt(EI/ρA)/L² = 13 rad/s) overdamped, ζ = τω1/2 = 1.3, its slow
  // pole at −6.2 1/s: after 3 s the motion has decayed by e^−15 (3e-7), and the rod at rest is
  // the static arc, so 1e-5 L is ample.
  SiliconeRod rod;
  const double tau = 0.2;
  rod.material.damping = {tau * rod.EI(),
                          tau * rod.material.shear_modulus * rod.section.torsion_constant,
                          tau * rod.material.shear_modulus * rod.section.area, tau * rod.EA()};
  const RodModel model = rod.Model({rod.At(Vec2(rod.offset, 0), 0, rod.length)});
  const double p =
      truth::ChamberPressureForTurn(0.5 * kPi, rod.EI(), rod.length, rod.chamber_area, rod.offset);
  Bdf2Options opt;
  opt.dt = 0.01;
  Bdf2ShootingStepper stepper(model, 41, opt);
  StepInput input;
  ASSERT_TRUE(stepper.InitializeAtRest(input).converged());
  for (int n = 1; n <= 300; ++n) {
    input.actuation.chamber_pressure[0] = p * std::min(1.0, n * opt.dt / 0.5);
    ASSERT_TRUE(stepper.Step(input).converged()) << n;
  }
  const double k = -truth::ChamberArcCurvature(p, rod.chamber_area, rod.offset, rod.EI());
  const double nu = truth::ChamberStretch(p * rod.chamber_area, rod.EA());
  const double error =
      (stepper.state().tip_position_W() - truth::BodyYArc(k, nu, rod.length).p).norm() / rod.length;
  std::printf("dynamics after the ramp: tip error %.3g L\n", error);
  EXPECT_LT(error, 1e-5);
}

TEST(Pneumatic, ChamberWrenchPushesAwayFromTheChamberOnlyWhereItRuns) {
  // The sign convention against the tendon law: a chamber at +x gives w = p A [r × e3; e3] =
  // p A [0, −x, 0, 0, 0, 1], so K⁻¹ w shifts κ2 negative (tangent turns to −x) and stretches.
  const std::vector<Chamber> chambers = {{"a", Vec2(0.004, 0.001), 2e-5, 0.1, 0.2}};
  const Actuation act = Pressures({5e4});
  const Vec6 w = ChamberWrench(chambers, 0.15, act);
  const double F = 5e4 * 2e-5;
  EXPECT_DOUBLE_EQ(w(0), F * 0.001);
  EXPECT_DOUBLE_EQ(w(1), -F * 0.004);
  EXPECT_EQ(w(2), 0.0);
  EXPECT_EQ(w.segment<2>(3), Vec2::Zero());
  EXPECT_DOUBLE_EQ(w(5), F);
  EXPECT_EQ(ChamberWrench(chambers, 0.05, act), Vec6::Zero());  // before the chamber
  EXPECT_EQ(ChamberWrench(chambers, 0.2, act), Vec6::Zero());   // [start, end)
  // A rod's grid puts nodes at the chamber ends.
  SiliconeRod rod;
  const RodModel model = rod.Model({rod.At(Vec2(rod.offset, 0), 0.05, 0.13)});
  const std::vector<double> b = model.Breakpoints();
  EXPECT_NE(std::find(b.begin(), b.end(), 0.13), b.end());
}

}  // namespace
}  // namespace cosserat
