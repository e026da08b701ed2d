#pragma once
/// \file
/// Buckling of a rod held too stiffly for one shot: a long pipe on a bore (the shot's exponent
/// (k/4EI)^{1/4} L past ~15), a rod in high tension. BucklingAnalysis shoots it in one piece and
/// fails at once; here the equilibrium is followed along the load path by multiple shooting
/// (StaticMultipleShootingSolver), its stability index comes from Jacobi fields carried piece by
/// piece (ColumnSolver::FieldsInPieces), the critical load is where the index first rises
/// (bisected on it), and the mode is the null vector of the tip conditions carried back through
/// the pieces. Loads only: multiple shooting has no tendons or pressure (docs/buckling.md).

#include "cosserat/analysis/buckling.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"

namespace cosserat {

class BucklingInPieces {
 public:
  /// Throws std::invalid_argument for a path that varies the actuation (tendons, pressure), a
  /// rod with tendons, or invalid options.
  BucklingInPieces(const RodModel& model, int num_nodes, ColumnEnds ends, const lie::SE3& base,
                   const LoadPath& path, const BucklingOptions& options = {});

  /// Scan, detect (the index rises), bisect on the index to options.lambda_tolerance (or as far
  /// as the solves near the critical point converge), and the mode. The summary's
  /// scan_sigma_min and sigma_min_ratio are NaN (no σ_min here). kPathFailed also where the
  /// index is not defined along the path (loads that are not conservative). state(): the
  /// pre-buckled equilibrium at λ_cr, or the last one reached.
  BucklingSummary FindCriticalLoad();

  const RodState& state() const { return found_ ? hi_state_ : solver_.state(); }
  /// Pieces of the last solve.
  int pieces() const { return solver_.pieces(); }

 private:
  /// Solves at λ (continuing from the last solution) and counts the unstable directions there
  /// (−1: not defined); false when the solve fails.
  bool SolveAt(const StaticLoads& loads, int* index, BucklingSummary* out);
  /// The scan along loads(t), t from 0 to t_max, from the solution at t = 0 with index0: the
  /// first bracket [*lo, *hi] where the index rises above index0 (true), bisected to
  /// `tolerance`; false with *lo the last t reached (*failed: a solve failed or the index was
  /// not defined).
  template <class LoadsAt>
  bool Scan(const LoadsAt& loads_at, double t_max, double first_step, double tolerance,
            int index0, double* lo, double* hi, bool* failed, BucklingSummary* out);
  /// The mode at the equilibrium `state` under `loads`; multiplicity from the index's rise.
  BucklingMode ModeAt(const StaticLoads& loads, const RodState& state, bool double_root) const;

  RodModel model_;
  lie::SE3 base_;
  LoadPath path_;
  BucklingOptions options_;
  ColumnSolver column_;
  StaticMultipleShootingSolver solver_;
  RodState hi_state_;  ///< the equilibrium at the upper end of the bisection's bracket
  int hi_index_ = -1;  ///< and its index
  bool found_ = false;
};

}  // namespace cosserat
