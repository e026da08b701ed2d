#pragma once
// Shared set-up of the quaternion-FD integrator tests: benchmark (a) of issue 4
// (bench/quatfd_rods.hpp) released from rest under gravity, tight tolerances, and the failure
// statuses every error-controlled integrator must give.
#include <gtest/gtest.h>

#include <limits>

#include "../bench/quatfd_rods.hpp"
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

}  // namespace cosserat::quatfd::testing
