// The implicit SDIRK4 integrator of the quaternion-FD rod (sdirk.hpp) against the truth: its
// fixed-step convergence order, the Rosenbrock integrator at tight tolerance, the unit-quaternion
// constraint, and a stable step map at the step sizes where the Rosenbrock step map is not
// (docs/performance.md; QuatFdDynamics.StepLimitIsTheRosenbrockStepMapNotTheOde).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "cosserat/quatfd/quatfd_integrate.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/rosenbrock.hpp"
#include "cosserat/quatfd/sdirk.hpp"
#include "support/quatfd_falling_rod.hpp"

namespace cosserat::quatfd {
namespace {

using L = QuatFdLayout;

using testing::FallingRod;
using testing::Tight;
using bench::Horizontal;

TEST(QuatFdSdirk, FixedStepErrorIsFourthOrder) {
  // Fixed steps of Step() (Newton converged to 1e-12 · tolerance scale, projection after each
  // step) over the first 0.05 s after the release of the undamped rubber rod: the tip error
  // against h = T/512 falls by 2⁴ per halving of h (observed 3.98, 3.75; the reference's own error, ~e/16 of the finest run, lowers the
  // second by ~0.1, so ±0.4).
  // The undamped rod is used because SDIRK4 has stage order 1: on the damped benchmark rod, whose
  // over-damped shear/rotary modes (λ ≈ −2.5e6 1/s) sit in the stiff limit and are driven by the
  // slow motion, the observed order drops to ~2.5 at h = 6–25 ms (the known order reduction of
  // DIRK methods, Hairer–Wanner IV.15); the error control sees it, so it costs steps, not accuracy.
  QuatFdOptions o;
  o.segments = 6;
  QuatFdModel model(RodModel::Uniform(0.5, CrossSection::Circle(0.005),
                                      Material::FromPoissonRatio(5e6, 0.5, 1100)),
                    Horizontal(), o);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  model.set_loads(loads);
  const int n = model.size();
  Eigen::VectorXd q0(n), v0(n);
  model.RestState(q0, v0);
  const double T = 0.05;
  const auto run = [&](int steps) {
    SdirkIntegrator integ(model, Tight(1e-12));
    Eigen::VectorXd y(2 * n), y_new(2 * n), err(2 * n);
    y << q0, v0;
    for (int k = 0; k < steps; ++k) {
      EXPECT_TRUE(integ.Step(y, T / steps, y_new, err)) << steps << " steps, step " << k;
      y = y_new;
      model.Project(y.head(n), y.tail(n));
    }
    return Vec3(y.segment<3>(L::X(6)));
  };
  const Vec3 ref = run(512);
  double e[3];
  const int steps[3] = {32, 64, 128};
  for (int k = 0; k < 3; ++k) e[k] = (run(steps[k]) - ref).norm();
  const double p1 = std::log2(e[0] / e[1]), p2 = std::log2(e[1] / e[2]);
  std::printf("tip error %.3g %.3g %.3g (h = T/32, T/64, T/128): orders %.2f %.2f\n", e[0], e[1],
              e[2], p1, p2);
  EXPECT_GT(e[2], 1e-13);  // above round-off, or the orders mean nothing
  EXPECT_NEAR(p1, 4.0, 0.4);
  EXPECT_NEAR(p2, 4.0, 0.4);
}

TEST(QuatFdSdirk, AgreesWithRosenbrockAtTightTolerance) {
  // Benchmark (a), N = 10, 0.3 s after the release, both integrators at
  // rel = abs = velocity tolerance 1e-8. Two different 4th-order methods with independent error
  // control: their difference is their global errors, a small multiple of the 1e-8 tolerance
  // scale; 1e-7 m (2e-7 of the rod length) leaves that margin and is far below what a wrong
  // stage or a drifting Newton iteration gives (6e-5 m seen with a too loose Newton norm).
  FallingRod s(10);
  Eigen::VectorXd tips[2];
  long steps[2];
  for (int k = 0; k < 2; ++k) {
    Eigen::VectorXd q = s.q, v = s.v;
    std::unique_ptr<QuatFdIntegrator> integ =
        MakeIntegrator(k == 0 ? IntegratorKind::kRosenbrock : IntegratorKind::kSdirk, s.model,
                       Tight(1e-8));
    double t = 0;
    ASSERT_EQ(integ->Advance(0.3, &t, q, v), IntegratorStatus::kOk) << integ->name();
    tips[k] = q.segment<3>(L::X(10));
    steps[k] = integ->stats().steps;
  }
  std::printf("tip z %.9f (rosenbrock, %ld steps) %.9f (sdirk, %ld steps)\n", tips[0][2], steps[0],
              tips[1][2], steps[1]);
  EXPECT_LT(tips[0][2], -0.1);  // it has fallen (the floppy rod nearly free-falls, −0.45 m)
  EXPECT_LT((tips[0] - tips[1]).norm(), 1e-7);
}

// Benchmark (b) (bench/quatfd_rods.hpp SteelString, bench_quatfd.cpp): steel
// string, 20 segments, top pinned, released horizontal, gravity, velocity_abs_tol at its default.
QuatFdModel SteelStringModel() {
  Material m = Material::FromShearModulus(200e9, 80e9, 7850);
  const CrossSection c = CrossSection::Circle(0.0005);
  m.damping.shear = 1e-5 * m.shear_modulus * c.area;
  m.damping.extension = 1e-5 * m.youngs_modulus * c.area;
  QuatFdOptions o;
  o.segments = 20;
  o.base_end = EndCondition::kPinned;
  QuatFdModel model(RodModel::Uniform(1.0, c, m), Horizontal(), o);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  model.set_loads(loads);
  return model;
}

TEST(QuatFdSdirk, SteelStringTipConvergesWithTheTolerance) {
  // The tip height 1 s after the release against Radau at 1e-9 (Radau 1e-8 and 1e-10 agree
  // with it to 2e-9 m; Rosenbrock at 1e-9 to 1.4e-6 m). SDIRK4 at rel = abs = 1e-7 and 1e-8, with
  // velocity_abs_tol left at 1e-3 as in the benchmark and the CLI. Its fixed-step global error
  // here falls about 10x per halving of h (order ~3.3, stage order 1) and the accepted h goes
  // like tol^(1/4), so 10x tighter should give about 6-10x less error; ≥ 4x is asked, and 2e-5 m
  // at 1e-8 (measured 7.1e-6 m). Before the integrated-velocity check (sdirk.cpp,
  // IntegratedVelocityError) the step was set by velocity_abs_tol alone over 1e-6 ... 1e-7: the
  // errors were 1.61e-4 m (1e-7) and 6.8e-5 m (1e-8), ratio 2.4, and 1e-6 gave the same as 1e-7.
  const QuatFdModel model = SteelStringModel();
  const int tip_z = L::X(20) + 2;
  auto tip = [&](IntegratorKind kind, double tol) {
    Eigen::VectorXd q(model.size()), v(model.size());
    model.RestState(q, v);
    IntegratorOptions io;
    io.rel_tol = io.abs_tol = tol;  // velocity_abs_tol stays at its default, 1e-3
    std::unique_ptr<QuatFdIntegrator> integ = MakeIntegrator(kind, model, io);
    double t = 0;
    EXPECT_EQ(integ->Advance(1.0, &t, q, v), IntegratorStatus::kOk) << integ->name();
    return q[tip_z];
  };
  const double reference = tip(IntegratorKind::kRadau, 1e-9);
  const double e7 = std::abs(tip(IntegratorKind::kSdirk, 1e-7) - reference);
  const double e8 = std::abs(tip(IntegratorKind::kSdirk, 1e-8) - reference);
  std::printf("steel string tip z at 1 s: radau(1e-9) %.10f, sdirk error %.3g (1e-7) %.3g (1e-8)\n",
              reference, e7, e8);
  EXPECT_LT(reference, -0.005);  // it has swung down (-8.0 mm)
  EXPECT_LT(e8, 2e-5);
  EXPECT_LT(e8, e7 / 4);
}

TEST(QuatFdSdirk, ConstraintStaysOnTheSphere) {
  // Benchmark (a) at the default tolerances over 2 s: after each step's projection
  // | |p| − 1 | is round-off (1e-10, the acceptance); the drift the projection undoes
  // is of the size of the local error, non-zero.
  // The co-rotated iteration matrix is what makes a Jacobian last many steps.
  testing::ExpectConstraintStaysOnTheSphere<SdirkIntegrator>();
}

TEST(QuatFdSdirk, StepMapIsStableWhereRosenbrocksIsNot) {
  // The state of benchmark (a) at t = 1 s, where one Rosenbrock step's map has spectral radius
  // ρ ≈ 20 at h = 5 ms (QuatFdDynamics.StepLimitIsTheRosenbrockStepMapNotTheOde). The SDIRK
  // step (Newton converged, projection) must be a contraction up to round-off at 5 and 20 ms:
  // the ODE's only growing directions are the ±|ṗ| gauge pairs (≤ 3.1 1/s), which the
  // projection removes, and the L-stable method damps the stiff ones. ρ is computed by central
  // differences (ε = 1e-6) of a Newton solution converged to 1e-10 · scale, so it is known to
  // ~1e-4: ρ ≤ 1 + 1e-3 is "no growth"; a leak of the turning stiff directions would give
  // ρ ≫ 1 as it does for the Rosenbrock step.
  FallingRod s(10);
  const int n = s.model.size();
  {
    SdirkIntegrator integ(s.model);
    double t = 0;
    ASSERT_EQ(integ.Advance(1.0, &t, s.q, s.v), IntegratorStatus::kOk);
  }
  const std::vector<int> keep = testing::FreeUnknowns(s.model);  // free unknowns of y = [q; v]
  Eigen::VectorXd y(2 * n);
  y << s.q, s.v;
  const auto spectral_radius = [&](QuatFdIntegrator& integ, double h) {
    return testing::StepMapSpectralRadius(
        s.model, y, keep, 1e-6,
        [&](const Eigen::VectorXd& yy, Eigen::VectorXd& out, Eigen::VectorXd& err) {
          bool ok = false;
          if (auto* sd = dynamic_cast<SdirkIntegrator*>(&integ))
            ok = sd->Step(yy, h, out, err);
          else
            ok = static_cast<RosenbrockIntegrator&>(integ).Step(yy, h, out, err);
          EXPECT_TRUE(ok);
        });
  };
  SdirkIntegrator sdirk(s.model, Tight(1e-10));
  RosenbrockIntegrator rosenbrock(s.model);
  const double rho_r5 = spectral_radius(rosenbrock, 5e-3);
  const double rho_s5 = spectral_radius(sdirk, 5e-3), rho_s20 = spectral_radius(sdirk, 20e-3);
  std::printf("step-map spectral radius at 5 ms: rosenbrock %.3g, sdirk %.6f; sdirk at 20 ms %.6f\n",
              rho_r5, rho_s5, rho_s20);
  EXPECT_GT(rho_r5, 2.0);
  EXPECT_LT(rho_s5, 1.0 + 1e-3);
  EXPECT_LT(rho_s20, 1.0 + 1e-3);

  // And fixed 10 ms steps for 1 s stay bounded and dissipate (Rosenbrock diverges within 4 at
  // 5 ms, docs/performance.md).
  Eigen::VectorXd out(2 * n), err(2 * n);
  const double e0 = s.model.Energy(s.q, s.v).total();
  SdirkIntegrator fixed(s.model);
  for (int k = 0; k < 100; ++k) {
    ASSERT_TRUE(fixed.Step(y, 10e-3, out, err)) << "step " << k;
    y = out;
    s.model.Project(y.head(n), y.tail(n));
  }
  ASSERT_TRUE(y.allFinite());
  EXPECT_LT(s.model.Energy(y.head(n), y.tail(n)).total(), e0);
}

TEST(QuatFdSdirk, FailureIsAStatus) {
  testing::ExpectFailuresAreStatuses<SdirkIntegrator>();
}

}  // namespace
}  // namespace cosserat::quatfd
