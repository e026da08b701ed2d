#include "cosserat/state/solve_status.hpp"

namespace cosserat {

const char* ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kNotRun:
      return "not_run";
    case SolveStatus::kConverged:
      return "converged";
    case SolveStatus::kMaxIterations:
      return "max_iterations";
    case SolveStatus::kLoadSteppingFailed:
      return "load_stepping_failed";
    case SolveStatus::kNonFinite:
      return "non_finite";
    case SolveStatus::kOutOfReach:
      return "out_of_reach";
    case SolveStatus::kUnderResolved:
      return "under_resolved";
  }
  return "unknown";
}

}  // namespace cosserat
