#pragma once
/// \file
/// Status of a solve, shared by the solvers.

namespace cosserat {

enum class SolveStatus {
  kNotRun,              ///< Solve() has not been called.
  kConverged,           ///< the dimensionless residual norm fell below Options::tolerance.
  kMaxIterations,       ///< Options::max_iterations reached without convergence, no stepping.
  kLoadSteppingFailed,  ///< continuation could not reach the full load: the load increment fell
                        ///< below Options::min_load_step or Options::max_load_steps was hit.
  kNonFinite,           ///< the integration produced NaN or Inf at every attempt.
  kOutOfReach,          ///< the equations have a root, but one no body can take: an inverse
                        ///< pose that needs a rod of zero or negative length.
  kUnderResolved,       ///< converged, but on a grid too coarse for the shape to mean much:
                        ///< the section turns by more than 1.5 rad per segment.
};

/// "converged", "max_iterations", "load_stepping_failed", "non_finite", "out_of_reach",
/// "under_resolved", "not_run".
const char* ToString(SolveStatus status);

}  // namespace cosserat
