#pragma once
// Shared set-up of the quaternion-FD integrator tests: benchmark (a), the rubber rod
// (bench/quatfd_rods.hpp) released from rest under gravity, tight tolerances, and the failure
// statuses every error-controlled integrator must give.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <vector>

#include "../../bench/quatfd_rods.hpp"
#include "cosserat/quatfd/integrator.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::quatfd::testing {

/// A rod (default: the benchmark rubber rod) clamped horizontally, at rest, gravity switched on.
struct FallingRod {
  QuatFdModel model;
  Eigen::VectorXd q, v;
  explicit FallingRod(int segments, const RodModel& rod = bench::RubberRod())
      : model(rod, bench::Horizontal(), [segments] {
          QuatFdOptions o;
          o.segments = segments;
          return o;
        }()) {
    StaticLoads loads;
    loads.gravity_W = Vec3(0, 0, -9.81);
    model.set_loads(loads);
    q.resize(model.size());
    v.resize(model.size());
    model.RestState(q, v);
  }
};

/// Every tolerance (relative, and absolute on q and v) set to tol.
inline IntegratorOptions Tight(double tol) {
  IntegratorOptions io;
  io.rel_tol = io.abs_tol = io.velocity_abs_tol = tol;
  return io;
}

/// A state f cannot be evaluated at (NaN velocity): every Newton iteration fails, the step
/// shrinks to min_dt and the run reports kStepSizeUnderflow, not a number. A step cap: kMaxSteps.
template <typename Integrator>
void ExpectFailuresAreStatuses() {
  const FallingRod s(4);
  {
    Eigen::VectorXd q = s.q, v = s.v;
    v[QuatFdLayout::X(2)] = std::numeric_limits<double>::quiet_NaN();
    IntegratorOptions io;
    io.min_dt = 1e-8;
    Integrator integ(s.model, io);
    double t = 0;
    EXPECT_EQ(integ.Advance(0.1, &t, q, v), IntegratorStatus::kStepSizeUnderflow);
    EXPECT_EQ(t, 0.0);
  }
  {
    Eigen::VectorXd q = s.q, v = s.v;
    IntegratorOptions io;
    io.max_steps = 3;
    Integrator integ(s.model, io);
    double t = 0;
    EXPECT_EQ(integ.Advance(1.0, &t, q, v), IntegratorStatus::kMaxSteps);
    EXPECT_GT(t, 0.0);
    EXPECT_LT(t, 1.0);
    // (q, v) are the state at t, not the one passed in: the rod released from rest is moving.
    EXPECT_GT(v.norm(), 0.0);
  }
}

/// The falling rod (10 segments) at the integrator's default tolerances over 2 s, in 0.1 s output
/// intervals: after each step's projection | |p| − 1 | stays at round-off (1e-10); the drift the
/// projection undoes is of the size of the local error, non-zero and far below 1e-4; and the
/// co-rotated iteration matrix lets a Jacobian last several steps.
template <typename Integrator>
void ExpectConstraintStaysOnTheSphere() {
  FallingRod s(10);
  Integrator integ(s.model);
  double t = 0, worst = 0;
  for (int k = 1; k <= 20; ++k) {
    ASSERT_EQ(integ.Advance(0.1 * k, &t, s.q, s.v), IntegratorStatus::kOk);
    worst = std::max(worst, s.model.ConstraintViolation(s.q));
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_GT(integ.stats().max_drift_before_projection, 0.0);
  EXPECT_LT(integ.stats().max_drift_before_projection, 1e-4);
  EXPECT_LT(integ.stats().jacobian_evaluations, integ.stats().steps);
}

/// The unknowns of y = [q; v] the model does not fix (indices into y).
inline std::vector<int> FreeUnknowns(const QuatFdModel& model) {
  const int n = model.size();
  std::vector<int> keep;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < n; ++i)
      if (!model.IsFixed(i)) keep.push_back(k * n + i);
  return keep;
}

/// Spectral radius of the one-step map y ↦ Project(step(y)) on the free unknowns `keep`, by
/// central differences of step eps. step(yy, out, err) advances the state yy = [q; v] by one step
/// into out.
template <typename Step>
double StepMapSpectralRadius(const QuatFdModel& model, const Eigen::VectorXd& y,
                             const std::vector<int>& keep, double eps, Step step) {
  const int n = model.size(), m = static_cast<int>(keep.size());
  Eigen::VectorXd out(2 * n), err(2 * n), d(2 * n);
  Eigen::MatrixXd D(m, m);
  for (int b = 0; b < m; ++b) {
    for (int sign : {1, -1}) {
      Eigen::VectorXd yy = y;
      yy[keep[b]] += sign * eps;
      step(yy, out, err);
      model.Project(out.head(n), out.tail(n));
      if (sign == 1)
        d = out;
      else
        d = (d - out) / (2 * eps);
    }
    for (int a = 0; a < m; ++a) D(a, b) = d[keep[a]];
  }
  return Eigen::EigenSolver<Eigen::MatrixXd>(D, false).eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace cosserat::quatfd::testing
