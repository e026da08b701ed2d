#include "cosserat/analysis/bend_radius.hpp"

#include <cmath>
#include <limits>

namespace cosserat {

namespace {

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
  auto finish = [&](double lambda, const char* limit) {
    out.load_factor = lambda;
    out.limit = limit;
    SmallestRadius(robot.state(), &out.min_radius, &out.s);
    return out;
  };
  double ratio = 0, good = 0;
  for (int k = 1; k <= steps; ++k) {
    const double lambda = static_cast<double>(k) / steps;
    if (!solve(lambda, &ratio)) {
      // Back to the last converged state: the radius reached before the solve failed.
      double r0;
      solve(good, &r0);
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

}  // namespace cosserat
