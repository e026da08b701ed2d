#include "cosserat/analysis/bend_radius.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosserat {

namespace {

constexpr double kPiValue = 3.14159265358979323846;

StaticLoads Combined(const StaticLoads& fixed, const StaticLoads& actuation, double lambda) {
  StaticLoads out = fixed;
  const StaticLoads a = actuation.Scaled(lambda);
  out.distributed_force_W += a.distributed_force_W;
  out.tip_force += a.tip_force;
  out.tip_force_frame = a.tip_force.any() ? a.tip_force_frame : fixed.tip_force_frame;
  out.tip_moment += a.tip_moment;
  out.tip_moment_frame = a.tip_moment.any() ? a.tip_moment_frame : fixed.tip_moment_frame;
  return out;
}

// Smallest 1/|κ⊥| over the nodes, and where.
void SmallestRadius(const RodState& st, double* radius, double* s) {
  *radius = std::numeric_limits<double>::infinity();
  for (int i = 0; i < st.size(); ++i) {
    const double kappa = st.strain[i].head<2>().norm();
    if (kappa > 0 && 1.0 / kappa < *radius) {
      *radius = 1.0 / kappa;
      *s = st.s[i];
    }
  }
}

// The result at the robot's current state (the last solve, at load factor lambda).
BendRadiusResult Finish(const EversionRobot& robot, BendRadiusResult out, double lambda,
                        const char* limit, double kink_ratio) {
  out.load_factor = lambda;
  out.limit = limit;
  out.kink_ratio = kink_ratio;
  SmallestRadius(robot.state(), &out.min_radius, &out.s);
  return out;
}

}  // namespace

BendRadiusResult MinimumBendRadius(EversionRobot& robot, const StaticLoads& fixed,
                                   const StaticLoads& actuation, int steps) {
  BendRadiusResult out;
  auto solve = [&](double lambda, double* kink_ratio) {
    ++out.solves;
    const EversionSolveSummary s = robot.Solve(Combined(fixed, actuation, lambda));
    *kink_ratio = s.kink.max_ratio;
    return s.solve.converged();
  };
  double ratio = 0, good = 0;
  auto finish = [&](double lambda, const char* limit) {
    return Finish(robot, out, lambda, limit, ratio);
  };
  // The fixed loads alone (its weight at this length) may already kink the tube: then no part
  // of the pattern bends it further before a kink, and the radius is that of a folded tube.
  if (!solve(0.0, &ratio)) return finish(0.0, "no_convergence");
  if (ratio >= 1.0) return finish(0.0, "kinked_by_fixed_loads");
  for (int k = 1; k <= steps; ++k) {
    const double lambda = static_cast<double>(k) / steps;
    if (!solve(lambda, &ratio)) {
      // Back to the last converged state: the radius reached before the solve failed.
      solve(good, &ratio);
      return finish(good, "no_convergence");
    }
    if (ratio >= 1.0) {
      // Kink onset between good and lambda: bisect on the moment ratio (monotone in λ here).
      double lo = good, hi = lambda;
      while (hi - lo > 1e-6 * hi) {
        const double mid = 0.5 * (lo + hi);
        double r;
        if (solve(mid, &r) && r < 1.0)
          lo = mid;
        else
          hi = mid;
      }
      solve(lo, &ratio);
      return finish(lo, "kink");
    }
    good = lambda;
  }
  return finish(1.0, "actuation");
}

BendRadiusResult BendRadiusAtTipAngle(EversionRobot& robot, const StaticLoads& fixed,
                                      const StaticLoads& actuation, double angle) {
  if (!(std::isfinite(angle) && angle > 0 && angle < kPiValue))
    throw std::invalid_argument("angle: must lie in (0, pi) rad");
  BendRadiusResult out;
  double kink = 0;
  // g(λ) = (tip angle at λ) − angle; NaN if the solve fails.
  auto g = [&](double lambda) -> double {
    ++out.solves;
    const EversionSolveSummary s = robot.Solve(Combined(fixed, actuation, lambda));
    if (!s.solve.converged()) return NAN;
    kink = s.kink.max_ratio;
    const RodState& st = robot.state();
    const double c = st.rotation_WB.front().col(2).dot(st.tip_rotation_WB().col(2));
    return std::acos(std::clamp(c, -1.0, 1.0)) - angle;
  };
  auto finish = [&](double lambda, const char* limit) {
    return Finish(robot, out, lambda, limit, kink);
  };
  double lo = 0, g_lo = -angle, hi = 1, g_hi = g(hi);
  for (int k = 0; k < 40 && g_hi < 0; ++k) {  // bracket by doubling
    lo = hi;
    g_lo = g_hi;
    hi *= 2;
    g_hi = g(hi);
  }
  if (!(g_hi >= 0)) {
    g(lo);
    return finish(lo, "no_convergence");
  }
  int side = 0;
  double x = hi, gx = g_hi;
  for (int it = 0; it < 100 && std::abs(gx) > 1e-10; ++it) {
    x = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    gx = g(x);
    if (std::isnan(gx)) {
      g(lo);
      return finish(lo, "no_convergence");
    }
    if (gx < 0) {
      lo = x;
      g_lo = gx;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    } else {
      hi = x;
      g_hi = gx;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    }
  }
  return finish(x, "angle");  // the last solve was at x: the robot holds that state
}

}  // namespace cosserat
