#pragma once
/// \file
/// Static equilibrium of the quaternion-FD rod: Newton on f(q, 0) = 0 with the exact banded
/// Jacobian ∂f/∂q, with load stepping when the full load does not converge.
///
/// At v = 0, f = 0 says: every free vertex is in force balance, every segment in moment balance,
/// and (through a Baumgarte term β² (|p|² − 1)/2 switched on for the solve) every quaternion is a
/// unit one. Newton is invariant under the row scaling by the lumped masses and the quaternion
/// mass matrix, so this is Newton on the discrete equilibrium equations themselves.

#include <Eigen/Core>

#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/state/solve_status.hpp"

namespace cosserat::quatfd {

struct QuatFdStaticsOptions {
  /// Convergence: the dimensionless residual (largest vertex force over EI/L², largest segment
  /// torque over EI/L, largest | |p|² − 1 |) falls below `tolerance`, or a Newton step changes no
  /// position by more than 1e-13 L and no quaternion entry by more than 1e-13 while the residual
  /// is below `floor_tolerance` (the round-off floor of stiff rods: EA/(EI/L²) ≈ 4 L²/r²), or
  /// below the residual's own round-off, ~10 ε C_Γ N |x|/L over the force scale, where that is
  /// larger (fine grids: 1e-6 at N = 30 000 for a 1 m rod of r = 5 mm). The
  /// scales are the largest segment force F_max and F_max L/N where they exceed EI/L² and EI/L:
  /// a taut cable's tension can be 10⁸ EI/L², and a slender rod hanging under its own weight
  /// (L/r ≥ 4 000) carries a weight whose round-off alone is above 1e-6 EI/L².
  double tolerance = 1e-10;
  double floor_tolerance = 1e-6;
  int max_iterations = 50;  ///< Newton iterations per load step
  bool load_stepping = true;
  /// Newton at the full load first (false: straight to the continuation from the rest state,
  /// which follows the loaded path where a direct solve can land on another equilibrium).
  bool direct_solve = true;
  /// The continuation's largest increment (fraction of the full load); and whether a solve that
  /// moves the vertices against the last increment's move counts as failed (a jump to another
  /// branch, such as a column's straight shape past its Euler load), so that it is halved.
  double max_load_step = 1.0;
  bool keep_path_direction = false;
  double min_load_step = 1.0 / 4096.0;  ///< smallest load increment (fraction of the full load)
  int max_load_steps = 400;

  bool IsValid(std::string* why) const;
};

struct QuatFdStaticsSummary {
  SolveStatus status = SolveStatus::kNotRun;
  int iterations = 0;  ///< Newton iterations, all load steps
  int load_steps = 0;  ///< continuation steps taken (0: the direct solve converged)
  double residual = 0;
  double wall_time_s = 0;
  bool converged() const { return status == SolveStatus::kConverged; }
};

/// Solves for the equilibrium under `loads` (set into the model). q holds the initial guess (the
/// rest state when in doubt) and receives the solution (or the last iterate on failure). The
/// model's own loads are left at `loads`. Throws std::invalid_argument when q is not of the
/// model's size().
QuatFdStaticsSummary SolveStatics(QuatFdModel* model, const StaticLoads& loads,
                                  Eigen::Ref<Eigen::VectorXd> q,
                                  const QuatFdStaticsOptions& options = {});

/// The dimensionless static residual of q (see QuatFdStaticsOptions::tolerance) under the model's
/// loads.
double StaticResidual(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& q);

/// Whether the move from state b to c takes the model's vertices against the move from a to b
/// (Σ (x_c − x_b)·(x_b − a) < 0 over the vertices): along a load path, a jump to another branch
/// (a rod bent by a side load landing near its unstable straight shape past the Euler load).
bool TurnsBack(const QuatFdModel& model, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
               const Eigen::VectorXd& c);

}  // namespace cosserat::quatfd
