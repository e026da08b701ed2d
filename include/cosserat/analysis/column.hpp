#pragma once
/// \file
/// Statics of a straight column with the end conditions of Euler buckling, by shooting on the
/// SE(3) strong form (the integrator and its exact tangent are StaticShootingSolver's).
///
/// The base pose `base` (R_WB, p_W of s = 0) defines the column axis e = R_WB e₃ and the lateral
/// directions R_WB e₁, R_WB e₂. Six unknowns u (dimensionless) and six residuals r:
///
/// | ends            | unknowns u                        | tip residuals r                   |
/// |-----------------|-----------------------------------|-----------------------------------|
/// | clamped–free    | W(0) = [m; n] ⊘ scale             | W(L) − W_tip (the cantilever)     |
/// | pinned–pinned   | θ₁, θ₂ (rad), m₃(0), n(0) ⊘ scale | lateral δ, axial force, m(L)      |
/// | clamped–clamped | W(0) ⊘ scale                      | lateral δ, axial force, R(L)      |
/// | clamped–pinned  | W(0) ⊘ scale                      | lateral δ, axial force, m(L)      |
///
/// - A pinned base: R(0) = R_WB Exp([θ₁, θ₂, 0]) turns freely about the two lateral axes, with
///   no bending moment, m₁(0) = m₂(0) = 0; its twist is held (θ₃ = 0, the torque m₃(0) is the
///   unknown reaction), otherwise a rigid spin about the axis would make the problem singular.
/// - The guided tip (all but clamped–free) may only slide along the axis: the lateral residuals
///   are (R_WB e₁,₂) · (p(L) − p(0)) / L, and the axial one is the force balance
///   e · (R(L) n(L) − F_tip,W) / (EI/L²), F_tip from `loads` (dead, or a follower turned with the
///   tip). The lateral parts of F_tip go into the guide, as reactions.
/// - A pinned tip has m(L) = M_tip (body frame, ÷ EI/L); a clamped tip keeps the base's
///   orientation: ½ vee(Q − Qᵀ) = 0 with Q = R_WBᵀ R(L) (rad), which fixes its twist too.
///
/// scale = [EI/L ×3, EI/L² ×3] as in StaticShootingSolver. Gravity and distributed forces act
/// along the whole rod as usual.

#include <string>
#include <vector>

#include "cosserat/analysis/column_ends.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

/// Multiple shooting's options for these ends (StaticMultipleShootingOptions: a pinned base, a
/// guided tip, a clamped one), the rest at their defaults.
StaticMultipleShootingOptions MultipleShootingOptionsFor(ColumnEnds ends);

struct ColumnSummary {
  SolveStatus status = SolveStatus::kNotRun;
  int iterations = 0;   ///< Newton iterations
  int shots = 0;        ///< integrations from 0 to L (each with its exact Jacobian)
  int load_steps = 0;   ///< converged steps of SolveFromUnloaded (0 for Solve)
  double residual = 0;  ///< final dimensionless residual norm
  bool converged() const { return status == SolveStatus::kConverged; }
};

/// Column statics for one model, grid and pair of end conditions. Solve() is a damped Newton
/// iteration from the current unknowns (a warm start: the previous solution, or what
/// set_unknowns gave), with minimum-norm steps so that an exactly singular direction (a rod
/// symmetric about its axis buckles in any plane) is left alone. It takes no load steps: the
/// caller follows the load path (BucklingAnalysis does).
class ColumnSolver {
 public:
  using StateTangent = StaticShootingSolver::StateTangent;

  ColumnSolver(const RodModel& model, int num_nodes, ColumnEnds ends,
               const StaticShootingOptions& options = {}, const Actuation& actuation = {});

  /// Equilibrium under `loads` from the current unknowns. Uses options.tolerance and
  /// options.max_iterations (Newton iterations). On success the unknowns and state() hold the
  /// solution; otherwise the unknowns are left as they were before the call.
  ColumnSummary Solve(const lie::SE3& base, const StaticLoads& loads);
  /// Equilibrium under `loads` followed from the straight, unloaded column: the loads scaled by
  /// λ from 0 to 1, each step warm-started from the last, the step doubled after a success and
  /// halved after a failure (options.min_load_step, options.max_load_steps, as the cantilever
  /// solver's load stepping), and never larger than options.max_load_increment in the
  /// dimensionless load (StaticLoadParameter): a full step from the straight column can land Newton
  /// on another branch (a taut wire, PL²/EI = 80, converged to a looped shape). Status
  /// kLoadSteppingFailed when the step falls below the minimum; state() then holds the last
  /// converged step (at least the unloaded column). Past a critical load this follows the
  /// straight branch wherever it is an equilibrium (a symmetric column), stable or not, and
  /// may jump from a side load's bent path to the state beside it: the run layer settles such
  /// an answer (settle_beside_instability.hpp); BucklingAnalysis is the tool for stability.
  ColumnSummary SolveFromUnloaded(const lie::SE3& base, const StaticLoads& loads);

  /// The dimensionless residual at the unknowns u; with J, its exact Jacobian d r / d u (tangent
  /// propagation); with record, the node states of the shot; with tangents, the shot's tangent
  /// along u at every node.
  Vec6 Residual(const lie::SE3& base, const StaticLoads& loads, const Vec6& u, Mat6* J = nullptr,
                RodState* record = nullptr, std::vector<StateTangent>* tangents = nullptr) const;
  /// The dimensionless residual of the tip conditions for the shot `record` (node states) and,
  /// with J, its derivative along the directions of the tangent T at the tip (18 × 6, rows as in
  /// StateTangent). Residual() is the shot from u followed by this.
  Vec6 TipResidual(const lie::SE3& base, const StaticLoads& loads, const RodState& record,
                   const StateTangent& T, Mat6* J = nullptr) const;
  /// The number of unstable directions of the equilibrium at u (the Morse index, MorseIndexOfShot
  /// with the column's base and tip conditions): 0 stable. Counts a double root (a rod symmetric
  /// about its axis buckling in any plane) twice. −1 where it is not defined: a follower tip
  /// force, a tip moment, drag, a torque held by a pinned base (none is conservative). From a
  /// shot of Residual with record and tangents at u; a pinned base turned from its frame is shot
  /// again, its torque field along the pin's twist axis (Start). The tip term counts
  /// eigenvalues below −zero (in units of EI/L): none by default, so that a bisection on the
  /// index meets det J's root on a straight column. Once a pin has turned, J linearises the
  /// torque along the section's axis and the index the conservative joint: their singular
  /// points can differ (a flat bar bent by a side load: J at 1.40 P_E, the index at 2.19, where
  /// its pins pass each other). Statics pass the cantilever's 1e-8 (past buckling a round rod has
  /// a circle of equilibria, along which the tip stiffness is singular to the solve's
  /// tolerance, ±1e-10 EI/L: StaticShootingSolver::StabilityIndexFromShot).
  int StabilityIndexFromShot(const lie::SE3& base, const StaticLoads& loads, const Vec6& u,
                             const RodState& record, const std::vector<StateTangent>& tangents,
                             double zero = 0.0) const;
  /// StabilityIndexFromShot at the current unknowns (a shot of its own).
  int StabilityIndexAtUnknowns(const lie::SE3& base, const StaticLoads& loads) const;

  /// The first-order change of the configuration along s for a change du of the unknowns at u:
  /// element i is the shot's StateTangent at node i times du (rows as in StateTangent). Used for
  /// buckling modes (du: the null vector of the Jacobian).
  std::vector<Eigen::Matrix<double, 18, 1>> Perturbation(const lie::SE3& base,
                                                         const StaticLoads& loads, const Vec6& u,
                                                         const Vec6& du) const;

  /// The Jacobi fields along an equilibrium `solved` found elsewhere on this grid (multiple
  /// shooting), whose single shot would amplify rounding beyond use, carried in `pieces` equal
  /// pieces: each shot from the solved state at its first node, started from the fields the
  /// last one ended with in an orthonormal basis of positive determinant (H = V U⁻¹, the inertia
  /// and Prüfer's W do not depend on the basis). No tendons.
  struct PiecewiseFields {
    Vec6 u = Vec6::Zero();                ///< the unknowns of the solved base state
    RodState record;                      ///< node states (each piece's own shot)
    std::vector<StateTangent> tangents;   ///< per node, in its piece's basis
    std::vector<int> first_node;          ///< of each piece
    /// Piece k's start fields are piece k − 1's end fields times basis_change[k] (identity for
    /// k = 0): coefficients c in piece k are basis_change[k] c in piece k − 1.
    std::vector<Mat6> basis_change;
    bool finite = false;                  ///< every shot stayed finite
  };
  PiecewiseFields FieldsInPieces(const lie::SE3& base, const StaticLoads& loads,
                                 const RodState& solved, int pieces) const;
  /// StabilityIndexFromShot on FieldsInPieces; −1 when a shot went non-finite.
  int StabilityIndexInPieces(const lie::SE3& base, const StaticLoads& loads, const RodState& solved,
                             int pieces, double zero = 0.0) const;

  /// The unknowns that start the shot at the base state R(0) (world) and W(0) = [m; n] (base
  /// body frame, N·m; N) found by another solver (multiple shooting): the inverse of the start
  /// map for these ends (a pinned base's rotations from R_WBᵀ R(0); its bending moment is zero).
  Vec6 UnknownsOf(const lie::SE3& base, const Mat3& R0, const Vec6& W0) const;

  void SetActuation(const Actuation& actuation) { shooter_.SetActuation(actuation); }
  const Vec6& unknowns() const { return u_; }
  void set_unknowns(const Vec6& u) { u_ = u; }
  /// The state of the last converged Solve.
  const RodState& state() const { return state_; }
  /// state() back to one this solver found before (a caller that refuses a solve's answer).
  void set_state(const RodState& state) { state_ = state; }
  /// state() back to what construction leaves: the grid, every other entry NaN (nothing solved).
  void ForgetState();
  ColumnEnds ends() const { return ends_; }
  double length() const { return shooter_.length(); }
  const std::vector<double>& grid() const { return shooter_.grid(); }
  const Vec6& scale() const { return scale_; }
  const StaticShootingOptions& options() const { return options_; }

 private:
  /// Start state of the shot (R(0), W(0)) and its tangent along u. A pinned base holds its
  /// torque about the base section's axis (body z: the moment it transmits turns with it, as
  /// Greenhill's shaft needs); with `for_index` the tangent along the torque is instead the
  /// pin's twist axis ν (pinned_base.hpp), the direction a conservative joint holding the
  /// rotations R_WB Exp([a, b, 0]) reacts along. The two have the same equilibria where the pin
  /// holds no torque (the only ones the index counts), and the same fields on a straight column;
  /// once the pin has turned, their fields differ.
  void Start(const lie::SE3& base, const Vec6& u, lie::SE3* start, Vec6* W0,
             StateTangent* dstart, bool for_index = false) const;
  /// StabilityIndexFromShot's conditions: conservative loads, no torque held by a pinned base.
  bool IndexIsDefined(const StaticLoads& loads, const Vec6& u) const;
  /// The index from Jacobi fields started as Start's `for_index` starts them.
  int CountIndex(const lie::SE3& base, const StaticLoads& loads, const RodState& record,
                 const std::vector<StateTangent>& tangents, double zero) const;
  /// FieldsInPieces, with Start's `for_index`.
  PiecewiseFields FieldsInPieces(const lie::SE3& base, const StaticLoads& loads,
                                 const RodState& solved, int pieces, bool for_index) const;

  StaticShootingSolver shooter_;
  ColumnEnds ends_;
  StaticShootingOptions options_;

  Vec6 scale_;
  RodModel model_;
  Vec6 u_ = Vec6::Zero();
  RodState state_;
};

}  // namespace cosserat
