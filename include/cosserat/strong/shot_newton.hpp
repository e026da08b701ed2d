#pragma once
/// \file
/// The Levenberg–Marquardt fallback every 6 × 6 shooting solve shares (statics, the BDF2 step,
/// the column), on ceres::TinySolver. A shot is any callable `Vec6 shot(const Vec6& x, Mat6* J)`
/// returning the dimensionless residual at the unknowns x and, when J is not null, writing its
/// exact Jacobian. The fast path before it (Newton with a secant-updated Jacobian from the last
/// solve) is in each solver, because what it may reuse differs: the stored shot of the last
/// statics solution, the BDF2 predictor and secant filter (secant_filter.hpp).

#include <ceres/tiny_solver.h>

#include "cosserat/lie/types.hpp"

namespace cosserat {

/// What a Levenberg–Marquardt run used.
struct ShotSolveCounts {
  int iterations = 0;  ///< LM iterations
  int shots = 0;       ///< shots evaluated (with or without the Jacobian)
  int jacobians = 0;   ///< of which with the Jacobian
};

namespace internal {

// The shot in the form ceres::TinySolver expects.
template <typename Shot>
struct TinySolverShot {
  using Scalar = double;
  enum { NUM_RESIDUALS = 6, NUM_PARAMETERS = 6 };
  Shot* shot;
  ShotSolveCounts* counts;
  Mat6* last_jacobian;

  bool operator()(const double* x_ptr, double* r_ptr, double* J_ptr) const {
    const Vec6 x = Eigen::Map<const Vec6>(x_ptr);
    Eigen::Map<Vec6> r(r_ptr);
    ++counts->shots;
    if (J_ptr) {
      Mat6 J;
      ++counts->jacobians;
      r = (*shot)(x, &J);
      Eigen::Map<Mat6> J_out(J_ptr);
      J_out = J;
      *last_jacobian = J;
    } else {
      r = (*shot)(x, nullptr);
    }
    return r.allFinite();
  }
};

}  // namespace internal

/// Levenberg–Marquardt from *x until |r| < tolerance or max_iterations steps; stops on the
/// residual only. Writes the last point to *x (not necessarily converged: the caller evaluates
/// it) and the Jacobian of the last shot with one to *last_jacobian (TinySolver evaluates it at
/// the accepted x last).
template <typename Shot>
ShotSolveCounts LevenbergMarquardtShot(Shot&& shot, double tolerance, int max_iterations, Vec6* x,
                                       Mat6* last_jacobian) {
  ShotSolveCounts counts;
  using Functor = internal::TinySolverShot<std::remove_reference_t<Shot>>;
  const Functor cost{&shot, &counts, last_jacobian};
  ceres::TinySolver<Functor> lm;
  lm.options.max_num_iterations = max_iterations + 1;  // TinySolver runs n − 1 steps
  lm.options.cost_threshold = 0.5 * tolerance * tolerance;
  lm.options.gradient_tolerance = 0.0;  // stop on the residual only
  lm.options.parameter_tolerance = 1e-15;
  lm.options.function_tolerance = 0.0;
  const auto& summary = lm.Solve(cost, x);
  counts.iterations = summary.iterations;
  return counts;
}

}  // namespace cosserat
