#pragma once
/// \file
/// Static cantilever by multiple shooting, for rods a single shot cannot resolve: along s the
/// linearised statics grows like e^{βs} on a stiff foundation (β = (k / 4EI)^{1/4}, k the
/// contact stiffness in N/m per m) and like e^{s sqrt(T/EI)} under a tension T, and a single
/// shot amplifies the error of its base unknowns by e^{βL} (double precision gives up near
/// βL ≈ 15–20).
///
/// The same discrete equations as StaticShootingSolver (RK4 on the grid with the section at the
/// nodes and midpoints; static_shooting.hpp), cut into pieces of about equal node count. Each
/// piece restarts at its junction from 12 unknowns (pose and body-frame wrench there), and the
/// junctions' continuity joins the tip condition as residual. Piece k depends only on its
/// start, so the Jacobian is block-banded: forward differences through each piece alone, about
/// 13 shots of the whole rod per Jacobian, and a banded LU O(pieces) (Ascher, Mattheij &
/// Russell 1995, ch. 4). Newton with backtracking at each load level, and natural continuation
/// in the loads from the unloaded rod (exact: the rest shape) or the last solution; when that
/// stalls on stiff contact surfaces, the loads are followed on surfaces 1000 times softer and
/// the surfaces then stiffened geometrically.
/// Ends held at points (the boundary "anchored", docs/cables.md): the base pinned, its unknowns
/// the rotation about the base frame's x and y, the torsional moment and the force; the tip
/// pinned at a point, its residual the position and the moment. The unloaded rest shape does not
/// meet the tip's point, so such a rod starts from a guess of the whole rod (SolveFrom).
/// The column ends of analysis/column.hpp (a pinned or clamped base, a tip guided along the
/// axis): from the unloaded rod, as the cantilever.
/// No tendons; no stability index (summary.stability_index = −1).

#include <functional>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

/// The exponent of a single static shot, for choosing pieces: the larger of β L over the
/// stiffest contact surface, β = (k / 4EI)^{1/4}, and sqrt(T / EI) L with T bounded by the
/// loads' total force (tip force plus the distributed force over L), EI the smaller bending
/// stiffness at s = 0 under `actuation` (an inflated tube's pressure). Dimensionless; 0 without
/// contact or load.
double StaticShootingExponent(const RodModel& rod, const StaticLoads& loads,
                              const Actuation& actuation = {});

/// A bound on the internal force the loads give a rod (N): the tip force plus L times the
/// distributed force at s = 0 (its weight, buoyancy and drag included), under `actuation`.
double LoadForceBound(const RodModel& rod, const StaticLoads& loads,
                      const Actuation& actuation = {});

struct StaticMultipleShootingOptions {
  /// Pieces; 0: chosen per Solve from StaticShootingExponent (1 up to an exponent of 10, else
  /// exponent / 5), at most the grid's segments.
  int pieces = 0;
  /// Convergence: the residual's 2-norm, dimensionless: positions ÷ L, rotations in rad,
  /// forces ÷ max(EI/L², F) and moments ÷ max(EI/L, sqrt(F EI)), F the loads' force (the tip
  /// force plus L times the distributed force) or SolveFrom's guess's largest, when larger.
  double tolerance = 1e-10;
  /// Newton iterations per load level.
  int max_iterations = 30;
  /// Load levels of the continuation (accepted and rejected) per Solve, besides the 1 / (the
  /// largest step) that max_load_increment asks for.
  int max_load_steps = 200;
  /// With tip_guided (a column), the largest step along the path in StaticLoadParameter units,
  /// as StaticShootingOptions::max_load_increment; cantilevers step by the whole load first.
  double max_load_increment = 3.0;
  /// Above 0 (rad): the path starts with a step of max_load_increment and takes a level only if
  /// no node's frame turned by more than this from the last one, the steps growing while it
  /// holds (a column's too: no longer capped at max_load_increment). A cantilever's whole step
  /// from the unloaded rod can land on an equilibrium far from the path, unstable: a soft rod
  /// held out level under its weight (w L³/EI = 430) looped up over its clamp.
  double max_turn = 0.0;
  /// The base pinned at its position instead of clamped: its rotation free but for the twist
  /// about the rod's axis (a clevis), which an isotropic rod pinned at both ends would otherwise
  /// leave undetermined; the base frame's z stays the reference of the held twist.
  bool base_pinned = false;
  /// The tip pinned at tip_position_W (world, m) instead of free; a tip force then acts on the
  /// anchor, not the rod, and a tip moment still loads the rod.
  bool tip_pinned = false;
  Vec3 tip_position_W = Vec3::Zero();
  /// With tip_pinned: the tip clamped at tip_rotation_W (R_WB) too, its residual the rotation
  /// error instead of the moment.
  bool tip_clamped = false;
  Mat3 tip_rotation_W = Mat3::Identity();
  /// The tip guided along the base frame's z axis e instead of free: a column's sliding end
  /// (analysis/column.hpp). Its residual is the lateral offset (base frame x and y, ÷ L), the
  /// axial force balance e · (R n − F_tip) (÷ EI/L²) and, with tip_clamped, the rotation
  /// relative to the base's (rad), else the moment balance as a free tip's. The lateral parts
  /// of the tip force go into the guide. Not with tip_pinned.
  bool tip_guided = false;
};

class StaticMultipleShootingSolver {
 public:
  /// Throws std::invalid_argument for an invalid model, a rod with tendons, fewer than 3 nodes
  /// or more pieces than segments. The section is taken under `actuation` (an inflated tube's
  /// pressure, a jamming vacuum), fixed for the solver's life.
  StaticMultipleShootingSolver(const RodModel& model, int num_nodes,
                               const StaticMultipleShootingOptions& options = {},
                               const Actuation& actuation = {});

  /// Equilibrium of the cantilever clamped at `base` under `loads`, by continuation from the
  /// last solution (or the unloaded rod). The state is valid when the status is converged.
  /// With a pinned tip, only after SolveFrom (throws std::logic_error otherwise).
  StaticShootingSummary Solve(const lie::SE3& base, const StaticLoads& loads);

  /// Equilibrium by Newton at the full loads from `guess`, a state of the whole rod on this grid
  /// (node poses, body-frame wrenches: e.g. the quaternion-FD equilibrium), the start of rods held
  /// at both ends. With options.pieces 0 the pieces follow from the guess's largest force T:
  /// exponent L sqrt(T / EI), as for Solve. The unknowns and residuals are scaled by the guess's
  /// largest force T (forces) and sqrt(T EI) (moments) instead of EI/L² and EI/L, and keep those
  /// scales for later solves on this object (options.tolerance is measured in them). Throws
  /// std::invalid_argument when the guess has another number of nodes.
  StaticShootingSummary SolveFrom(const lie::SE3& base, const StaticLoads& loads,
                                  const RodState& guess);

  const RodState& state() const { return state_; }
  /// Pieces of the last Solve.
  int pieces() const { return static_cast<int>(junction_nodes_.size()) + 1; }

 private:
  /// The state a piece starts from or arrives with: pose, and wrench in the body frame.
  using Point = rhs::StaticPoint<double>;
  void SetPieces(int pieces);
  /// The scales of the unknowns and residuals for a rod carrying forces up to `force` (N):
  /// max(EI/L², force) for forces, max(EI/L, sqrt(force EI)) for moments (a boundary layer of
  /// length sqrt(EI/force)); the base unknowns keep their values in physical units at `base`.
  void SetScales(const lie::SE3& base, double force);
  /// Integrates piece k from `start` under loads; the arriving state, and with record the node
  /// values of the piece.
  Point ShootPiece(int k, const Point& start, const StaticLoads& loads, bool record);
  /// The base state from the 6 scaled base unknowns x (docs at StaticMultipleShootingOptions).
  Point BaseStart(const lie::SE3& base, const Vec6& x) const;
  /// The base unknowns that BaseStart maps to the guess's state at s = 0.
  Vec6 BaseUnknowns(const lie::SE3& base, const Point& guess) const;
  /// Pieces for a rod whose single shot has this exponent (options.pieces when set).
  int PiecesFor(double exponent) const;
  /// The state recorded from the unknowns under `last`, and the summary's status and residual.
  void Finish(const lie::SE3& base, const StaticLoads& last, bool converged,
              StaticShootingSummary* summary);
  /// [mismatch of junction 0, 1, …; tip residual] at the current unknowns.
  bool Residual(const lie::SE3& base, const StaticLoads& loads, Eigen::VectorXd* r);
  /// Mismatch of junction k (12, dimensionless) between the arriving state and its restart.
  Eigen::Matrix<double, 12, 1> Mismatch(const Point& arriving, const Point& restart) const;
  Vec6 TipResidual(const lie::SE3& base, const Point& tip, const StaticLoads& loads) const;
  /// A junction state moved by the 12 dimensionless unknowns dz (right perturbation of R).
  Point Moved(const Point& y, const Eigen::Ref<const Eigen::VectorXd>& dz) const;
  bool Jacobian(const lie::SE3& base, const StaticLoads& loads, StaticShootingSummary* summary);
  /// Newton with backtracking until the residual's norm is below `tolerance`.
  bool Newton(const lie::SE3& base, const StaticLoads& loads, double tolerance,
              StaticShootingSummary* summary);
  /// Natural continuation along at(μ), μ: 0 → 1, from the current unknowns (a solution at
  /// μ = 0), with a secant predictor; a step doubles after a success and halves after a failure.
  /// No step exceeds max_step (a fraction of the path). Returns the last μ reached, the unknowns
  /// at it; counts the levels tried in *levels.
  /// The first step is first_step; with options.max_turn a level whose nodes turned more than
  /// that from the last one's fails like a Newton failure.
  double FollowPath(const lie::SE3& base, const std::function<StaticLoads(double)>& at,
                    double first_step, double max_step, int* levels,
                    StaticShootingSummary* summary);
  /// After a path to loads with contact surfaces stopped short: the loads followed from the
  /// unloaded rod on softened surfaces, which then stiffen. True when that reaches the loads
  /// (the unknowns are then their solution); else the unknowns are left as they were.
  bool FollowOntoStiffSurfaces(const lie::SE3& base, const StaticLoads& loads, int* levels,
                               StaticShootingSummary* summary);
  /// The first and the largest step (fractions of the path) of a path from `from` to `to`.
  void StepsAlong(const StaticLoads& from, const StaticLoads& to, double* first_step,
                  double* max_step) const;
  /// The node states the current unknowns give under `loads` (records state_).
  const RodState& Shot(const lie::SE3& base, const StaticLoads& loads);
  /// b moved on by t times its change from a (the secant predictor of the continuation).
  static Point Extrapolated(const Point& a, const Point& b, double t);
  /// The unloaded rod at `base`: the rest shape, exact for zero loads.
  void StartUnloaded(const lie::SE3& base);

  RodModel model_;
  StaticMultipleShootingOptions options_;
  Actuation actuation_;
  std::vector<double> grid_;
  std::vector<StaticShootingSolver::Sample> samples_;
  Vec6 scale_ = Vec6::Ones();  ///< W = scale ⊙ x: [moment ×3, force ×3] (SetScales)
  double guess_force_ = 0.0;  ///< the largest force of SolveFrom's guess, N (0 before one)
  RodState state_;

  std::vector<int> junction_nodes_;  ///< junction k restarts at node junction_nodes_[k]
  Vec6 x_ = Vec6::Zero();            ///< the base wrench, scaled
  std::vector<Point> junctions_;     ///< the restart states
  bool has_solution_ = false;
  lie::SE3 solved_base_;
  StaticLoads solved_loads_;

  Eigen::VectorXd r_, r_trial_, dx_;
  BandedMatrix lu_;
};

}  // namespace cosserat
