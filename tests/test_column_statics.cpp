// Column statics (ColumnSolver::SolveFromUnloaded) against the closed forms of small-deflection
// beam theory: a pinned-pinned beam in tension under a uniform lateral load (the taut cable with
// bending stiffness: stay cables, risers), and clamped-clamped and clamped-pinned beams under a
// uniform load.
#include <gtest/gtest.h>

#include <cmath>

#include "cosserat/analysis/column.hpp"
#include "support/analytic/tensioned_beam.hpp"
#include "support/analytic/timoshenko_beam.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

// A steel wire along +z from the origin, L = 0.5 m, r = 1 mm (r/L = 1/500), at 41 nodes. The
// loads are chosen for a mid-span deflection ~1e-4 L: geometric nonlinearity is then O(slope²)
// ~ 1e-7 relative. What separates the rod from Euler–Bernoulli is shear (below) and, under
// tension, extension; RK4 at h = L/40 is ~1e-8.
struct Wire : testing::SteelRod {
  Wire() : testing::SteelRod{0.5, 1e-3} {}
};

// Lateral (x) deflection of the node nearest mid-span.
double MidSpanDeflection(const ColumnSolver& solver) {
  const RodState& state = solver.state();
  return state.position_W[state.size() / 2].x();
}

TEST(ColumnStatics, TautPinnedBeamMatchesTheTensionedBeamSolution) {
  // EI y'''' − T y'' = q, y = y'' = 0 at both ends:
  // y(L/2) = q L² / 8T − (q EI / T²)(1 − 1 / cosh(kL/2)), k = sqrt(T / EI).
  // kL = 5: bending and tension both matter (the string alone would be 1.5 times off here).
  // Tension stretches the rod by T/EA = 2.5e-5, which lengthens the loaded span and its sag by
  // a few T/EA; shear adds ~3e-5 (pinned-pinned, below). 5e-4 (measured +3.9e-5).
  const Wire wire;
  const double T = 25 * wire.EI() / (wire.length * wire.length);
  const double q = 8 * T * 5e-5 / wire.length;  // N/m, for a string sag of 1e-4 L
  ColumnSolver solver(wire.model(), 41, ColumnEnds::kPinnedPinned);
  StaticLoads loads;
  loads.distributed_force_W = Vec3(q, 0, 0);
  loads.tip_force = Vec3(0, 0, T);  // pulls the guided tip along the axis
  const ColumnSummary s = solver.SolveFromUnloaded(lie::SE3{}, loads);
  ASSERT_TRUE(s.converged()) << ToString(s.status);
  const double expected = truth::TensionedBeamMidSpanDeflection(q, T, wire.EI(), wire.length);
  EXPECT_NEAR(MidSpanDeflection(solver) / expected, 1.0, 5e-4);
  // The pins carry no bending moment; the base reaction balances the lateral load by symmetry.
  EXPECT_NEAR(solver.state().wrench_B.front().head<2>().norm(), 0.0,
              1e-10 * wire.EI() / wire.length);
  EXPECT_NEAR(solver.state().BaseReaction_W().tail<3>().x(), -q * wire.length / 2,
              5e-4 * q * wire.length / 2);
}

TEST(ColumnStatics, BeamsUnderAUniformLoadMatchTimoshenko) {
  // No axial force (the guided tip slides freely). Euler–Bernoulli mid-span deflections:
  // clamped–clamped q L⁴ / 384 EI, pinned–pinned 5 q L⁴ / 384 EI, clamped (s = 0) – pinned
  // (s = L) q L⁴ / 192 EI (y = q x² (L − x)(3L − 2x) / 48 EI). Shear adds q L² / 8 κGA at
  // mid-span for the first two (Timoshenko): relative 12 (E/κG)(r/L)² = 1.36e-4 and
  // 2.4 (E/κG)(r/L)² = 2.72e-5, asserted to 2e-5 (measured 1.360e-4 and 2.69e-5). For the
  // propped cantilever, the Euler–Bernoulli value to 5e-4 (measured +8.1e-5).
  const Wire wire;
  const double q = 384 * wire.EI() * 5e-5 / std::pow(wire.length, 3);
  StaticLoads loads;
  loads.distributed_force_W = Vec3(q, 0, 0);
  const double L = wire.length, EI = wire.EI(), kGA = wire.kGA();
  struct Case {
    ColumnEnds ends;
    double expected, tolerance;
  };
  for (const Case& c :
       {Case{ColumnEnds::kClampedClamped, truth::ClampedClampedUniformLoadMidSpan(q, L, EI, kGA),
             2e-5},
        Case{ColumnEnds::kPinnedPinned, truth::PinnedPinnedUniformLoadMidSpan(q, L, EI, kGA), 2e-5},
        Case{ColumnEnds::kClampedPinned, truth::ClampedPinnedUniformLoadMidSpan(q, L, EI), 5e-4}}) {
    ColumnSolver solver(wire.model(), 41, c.ends);
    const ColumnSummary s = solver.SolveFromUnloaded(lie::SE3{}, loads);
    ASSERT_TRUE(s.converged()) << ToString(c.ends) << ": " << ToString(s.status);
    EXPECT_NEAR(MidSpanDeflection(solver) / c.expected, 1.0, c.tolerance) << ToString(c.ends);
  }
}

TEST(ColumnStatics, LoadSteppingReportsWhereItStops) {
  // One Newton iteration allowed per step and steps no smaller than 1/4: a lateral load of
  // PL²/EI ~ 4 (a deflection ~0.3 L) needs more, so the stepping gives up with its status,
  // keeping the last converged step (if any) in state().
  const Wire wire;
  StaticShootingOptions options;
  options.max_iterations = 1;
  options.min_load_step = 0.25;
  ColumnSolver solver(wire.model(), 41, ColumnEnds::kPinnedPinned, options);
  StaticLoads loads;
  loads.distributed_force_W = Vec3(30 * wire.EI() / std::pow(wire.length, 3), 0, 0);
  const ColumnSummary s = solver.SolveFromUnloaded(lie::SE3{}, loads);
  EXPECT_EQ(s.status, SolveStatus::kLoadSteppingFailed);
  // What state() holds is an equilibrium the stepping reached: the guided tip still on the axis.
  const Vec3 tip = solver.state().position_W.back();
  ASSERT_TRUE(tip.allFinite());
  EXPECT_NEAR(tip.x(), 0.0, 1e-9 * wire.length);
  EXPECT_GT(tip.z(), 0.5 * wire.length);
  // Tight steps converge in one iteration, the full load does not: a few steps were taken.
  const ColumnSummary easy = ColumnSolver(wire.model(), 41, ColumnEnds::kPinnedPinned, options)
                                 .SolveFromUnloaded(lie::SE3{}, loads.Scaled(1e-6));
  EXPECT_TRUE(easy.converged()) << ToString(easy.status);
}

}  // namespace
}  // namespace cosserat
