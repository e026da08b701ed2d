// The Radau IIA integrator of the quaternion-FD rod (radau.hpp): the complex banded LU it needs,
// its fixed-step convergence order, agreement with the SDIRK and Rosenbrock integrators at tight
// tolerance, the unit-quaternion constraint, and failures reported as a status.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <memory>

#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/quatfd_integrate.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/radau.hpp"
#include "support/quatfd_falling_rod.hpp"

namespace cosserat::quatfd {
namespace {

using L = QuatFdLayout;

using testing::FallingRod;
using testing::Tight;
using bench::Horizontal;

TEST(QuatFdRadau, ComplexBandedLuSolves) {
  // A random diagonally weighted complex band matrix (n = 30, kl = 3, ku = 2) against Eigen's
  // dense LU: both are backward stable, the matrix is well conditioned (diagonal 4 against
  // off-diagonals ≤ 1), so the solutions agree to ~1e-15 relative; 1e-12 is round-off.
  const int n = 30, kl = 3, ku = 2;
  ComplexBandedMatrix M(n, kl, ku);
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i)
      M(i, j) = std::complex<double>(std::sin(1.3 * i + 0.7 * j), std::cos(0.4 * i - 2.1 * j)) +
                (i == j ? std::complex<double>(0.5, 4.0) : 0.0);
  const Eigen::MatrixXcd D = M.ToDense();
  Eigen::VectorXcd b(n);
  for (int i = 0; i < n; ++i) b[i] = std::complex<double>(std::cos(i), 0.3 * i);
  const Eigen::VectorXcd x_ref = D.partialPivLu().solve(b);
  ASSERT_TRUE(M.Factorize());
  Eigen::VectorXcd x = b;
  M.Solve(x);
  EXPECT_LT((x - x_ref).norm() / x_ref.norm(), 1e-12);
}

TEST(QuatFdRadau, FixedStepErrorIsFifthOrder) {
  // Fixed steps over the first 0.05 s after the release of the undamped rubber rod (as the SDIRK
  // test: undamped, so no over-damped stiff modes). The steps are made fixed through Advance
  // with initial_dt = max_dt = h and a loose tolerance (1e-2: the error test never rejects),
  // so that Newton starts from the extrapolated collocation polynomial as in a real run; Newton
  // is converged to κ = 1e-11 of that scale (1e-13 absolute), below the errors measured. That
  // is close to round-off, where a Newton iteration may fail to contract and halve one step
  // (seen once at κ = 1e-12 after a round-off-level change of the complex LU): at most one
  // such step is allowed; it only makes that run slightly more accurate.
  // Projection after each step. Against h = T/256 (its steps not checked: a few Newton
  // failures at this κ halve some of them, which only makes the reference more accurate) the
  // tip error falls by 2⁵ per halving from h = T/32 to T/64 (observed 4.93; ±0.5 covers the
  // reference's own error, ~1/1000 of the finest run's, and the Newton error). From T/16
  // (3.1 ms) to T/32 the observed order is 4.05: h is not yet small against the undamped rod's
  // fast axial/shear vibrations, so only ≥ 3.5 is asked there.
  FallingRod s(6, RodModel::Uniform(0.5, CrossSection::Circle(0.005),
                                    Material::FromPoissonRatio(5e6, 0.5, 1100)));
  const double T = 0.05;
  const auto run = [&](int steps, bool check) {
    IntegratorOptions io = Tight(1e-2);
    io.initial_dt = io.max_dt = T / steps;
    RadauIntegrator integ(s.model, io);
    // With the component measure the controller stays out at 1e-2 (h = max_dt throughout, the
    // step counts asserted below); the physical one, which holds ω of the undamped fast
    // vibrations in rad/s, shortens one step at T/64 (65 steps): no longer a fixed-step run.
    integ.set_error_measure(RadauErrorMeasure::kComponents);
    integ.set_newton_kappa(1e-11);
    Eigen::VectorXd q = s.q, v = s.v;
    double t = 0;
    EXPECT_EQ(integ.Advance(T, &t, q, v), IntegratorStatus::kOk);
    if (check) {
      EXPECT_LE(integ.stats().rejected, 1);
      EXPECT_LE(integ.stats().steps, steps + 4 * integ.stats().rejected);  // h/2, then the cap
      EXPECT_GE(integ.stats().steps, steps);
    }
    return Vec3(q.segment<3>(L::X(6)));
  };
  const Vec3 ref = run(256, false);
  double e[3];
  const int steps[3] = {16, 32, 64};
  for (int k = 0; k < 3; ++k) e[k] = (run(steps[k], true) - ref).norm();
  const double p1 = std::log2(e[0] / e[1]), p2 = std::log2(e[1] / e[2]);
  std::printf("tip error %.3g %.3g %.3g (h = T/16, T/32, T/64): orders %.2f %.2f\n", e[0], e[1],
              e[2], p1, p2);
  EXPECT_GT(e[2], 1e-13);  // above round-off, or the orders mean nothing
  EXPECT_GT(p1, 3.5);
  EXPECT_NEAR(p2, 5.0, 0.5);
}

TEST(QuatFdRadau, AgreesWithSdirkAndRosenbrockAtTightTolerance) {
  // Benchmark (a), N = 10, 0.3 s after the release, the three stiff integrators at
  // rel = abs = velocity tolerance 1e-8 (the SDIRK test's setting). Independent methods and
  // error controls: their differences are their global errors, a small multiple of the 1e-8
  // tolerance scale; 1e-7 m (2e-7 of the rod length) leaves that margin and is far below what a
  // wrong coefficient or a drifting Newton iteration gives (1e-5 m and more).
  FallingRod s(10);
  const IntegratorKind kinds[3] = {IntegratorKind::kRadau, IntegratorKind::kSdirk,
                                   IntegratorKind::kRosenbrock};
  Eigen::VectorXd tips[3];
  long steps[3];
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd q = s.q, v = s.v;
    std::unique_ptr<QuatFdIntegrator> integ = MakeIntegrator(kinds[k], s.model, Tight(1e-8));
    double t = 0;
    ASSERT_EQ(integ->Advance(0.3, &t, q, v), IntegratorStatus::kOk) << integ->name();
    tips[k] = q.segment<3>(L::X(10));
    steps[k] = integ->stats().steps;
  }
  std::printf("tip z %.9f (radau, %ld steps) %.9f (sdirk, %ld) %.9f (rosenbrock, %ld)\n",
              tips[0][2], steps[0], tips[1][2], steps[1], tips[2][2], steps[2]);
  EXPECT_LT(tips[0][2], -0.1);  // it has fallen
  EXPECT_LT((tips[0] - tips[1]).norm(), 1e-7);
  EXPECT_LT((tips[0] - tips[2]).norm(), 1e-7);
}

TEST(QuatFdRadau, ConstraintStaysOnTheSphere) {
  // Benchmark (a) at the default tolerances over 2 s, in 0.1 s output intervals (Advance
  // continues with its polynomial and step): after each step's projection | |p| − 1 | is
  // round-off (1e-10, the acceptance); the drift the projection undoes is of the
  // size of the local error, non-zero and far below 1e-4.
  // The co-rotated iteration matrix lets a Jacobian last several steps.
  testing::ExpectConstraintStaysOnTheSphere<RadauIntegrator>();
}

TEST(QuatFdRadau, PhysicalErrorMeasureAgainstATightReference) {
  // RadauErrorMeasure::kPhysical (rotation and ω errors in rad, rad/s; the |p| gauge not
  // measured) against the truth: benchmark (b), the steel string pinned at the top, released
  // horizontally, over 3 s, and a reference at rel = abs = velocity tolerance 1e-7 with the
  // default measure (1e-7 and 1e-9 agree to 1e-10 m at 3 s). Measured (tip at 3 s, m, off the
  // reference; steps, rejected): at 1e-5 components 1.6e-6 (1 801, 378), physical 4.6e-7
  // (1 853, 41); at 1e-6 components 1.0e-6 (1 478, 35), physical 2.0e-8 (1 981, 1). The step
  // sequence of (b) follows round-off, so the bounds leave a margin: the
  // physical measure must be at least as accurate as the component measure's measured errors
  // (3e-6 and 1.5e-6: ~2× them), and the rejections caused by p·δṗ (21 % of the steps at 1e-5
  // with the component measure) must be gone (< 5 %, measured 2.2 %).
  QuatFdOptions opt;
  opt.segments = 20;
  opt.base_end = EndCondition::kPinned;
  QuatFdModel model(bench::SteelString(), Horizontal(), opt);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  model.set_loads(loads);
  Eigen::VectorXd q0(model.size()), v0(model.size());
  model.RestState(q0, v0);
  const double T = 3.0;
  const auto run = [&](const IntegratorOptions& io, RadauErrorMeasure measure, long* steps,
                       long* rejected) {
    RadauIntegrator integ(model, io);
    integ.set_error_measure(measure);
    Eigen::VectorXd q = q0, v = v0;
    double t = 0;
    EXPECT_EQ(integ.Advance(T, &t, q, v), IntegratorStatus::kOk);
    if (steps) *steps = integ.stats().steps;
    if (rejected) *rejected = integ.stats().rejected;
    return Vec3(q.segment<3>(L::X(20)));
  };
  const Vec3 ref = run(Tight(1e-7), RadauErrorMeasure::kComponents, nullptr, nullptr);
  EXPECT_LT(ref.z(), -0.05);  // it has swung down
  const double tols[2] = {1e-5, 1e-6}, bounds[2] = {3e-6, 1.5e-6};
  for (int k = 0; k < 2; ++k) {
    IntegratorOptions io;
    io.rel_tol = io.abs_tol = tols[k];  // velocity_abs_tol stays at its default, 1e-3
    long steps_c, rejected_c, steps_p, rejected_p;
    const double err_c =
        (run(io, RadauErrorMeasure::kComponents, &steps_c, &rejected_c) - ref).norm();
    const double err_p =
        (run(io, RadauErrorMeasure::kPhysical, &steps_p, &rejected_p) - ref).norm();
    std::printf("tol %g: components %.3e m (%ld steps, %ld rejected), physical %.3e m (%ld, %ld)\n",
                tols[k], err_c, steps_c, rejected_c, err_p, steps_p, rejected_p);
    EXPECT_LT(err_p, bounds[k]);
    EXPECT_LT(rejected_p, 0.05 * steps_p);
  }
}

TEST(QuatFdRadau, PhysicalErrorMeasureOnTheRubberRod) {
  // Benchmark (a), N = 10, over 2 s at rel_tol = abs_tol = 1e-6 (velocity_abs_tol 1e-3), against
  // a reference at all tolerances 1e-9: both measures hold the tip to ~0.1 of abs_tol (measured
  // 1.0e-7 and 9.9e-8 m; over the 10 s run at most 2.3e-7 and 1.7e-7 m); the physical one takes
  // ~7 % more steps for it. Bound: abs_tol.
  FallingRod s(10);
  const auto run = [&](const IntegratorOptions& io, RadauErrorMeasure measure) {
    RadauIntegrator integ(s.model, io);
    integ.set_error_measure(measure);
    Eigen::VectorXd q = s.q, v = s.v;
    double t = 0;
    EXPECT_EQ(integ.Advance(2.0, &t, q, v), IntegratorStatus::kOk);
    return Vec3(q.segment<3>(L::X(10)));
  };
  const Vec3 ref = run(Tight(1e-9), RadauErrorMeasure::kComponents);
  IntegratorOptions io;
  io.rel_tol = io.abs_tol = 1e-6;
  const double err_c = (run(io, RadauErrorMeasure::kComponents) - ref).norm();
  const double err_p = (run(io, RadauErrorMeasure::kPhysical) - ref).norm();
  std::printf("rubber rod, 2 s: components %.3e m, physical %.3e m off\n", err_c, err_p);
  EXPECT_LT(err_p, 1e-6);
  EXPECT_LT(err_c, 1e-6);
}

TEST(QuatFdRadau, FailureIsAStatus) {
  testing::ExpectFailuresAreStatuses<RadauIntegrator>();
}

}  // namespace
}  // namespace cosserat::quatfd
