#pragma once
/// \file
/// Static cantilever by shooting on the SE(3) strong form with V = 0 (FD notes 2025, eqs. 14, 16).
///
/// Unknowns: the internal wrench at the base, W(0) = [m; n] in the base body frame (6).
/// Integrate in s from 0 to L with fixed-step RK4 on the grid nodes (4th order), with the
/// rotation R as 9 numbers (orthogonal to O(h⁴)):
///   p' = R Γ,  R' = R K̂,  m' = −K × m − Γ × n,  n' = −K × n − Rᵀ f_W,
///   ξ = [K; Γ] = ξ* + K(s)⁻¹ [m; n]  (body-frame wrench W = [m; n] = −Λ of FD notes 2025),
/// where f_W = ρ A g + the distributed force (N/m). The residual is the tip condition
/// W(L) − W_tip in the tip body frame; Levenberg–Marquardt (ceres::TinySolver) with an exact
/// Jacobian (tangent propagation through the integrator) drives it to zero.

#include <array>
#include <chrono>
#include <limits>
#include <string>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/state/solve_status.hpp"

namespace cosserat {

struct StaticShootingOptions {
  /// Convergence: ‖r‖₂ < tolerance, with the residual made dimensionless by the moment scale
  /// EI/L and the force scale EI/L² (EI: the largest bending stiffness at s = 0).
  double tolerance = 1e-10;
  /// Levenberg–Marquardt iterations per solve (per load step when stepping).
  int max_iterations = 50;
  /// Reuse the Jacobian of the last solve (Broyden-updated quasi-Newton) before falling back to
  /// LM. This is what makes a warm re-solve cost a few shots.
  bool reuse_jacobian = true;
  /// Continuation in the load when a direct solve fails.
  bool load_stepping = true;
  /// Largest load increment per solve, measured as the change of the rigid-body base wrench in
  /// units of EI/L and EI/L² (for a tip force P that is PL²/EI). Larger changes are applied in
  /// steps, whatever load_stepping says, so the solver follows the equilibrium branch it starts
  /// on instead of jumping to a folded one (the elastica has several for PL²/EI ≳ 10).
  double max_load_increment = 3.0;
  /// Give up when the load increment falls below this fraction of the full load.
  double min_load_step = 1.0 / 4096.0;
  /// Hard cap on load steps (successful and failed) in one Solve.
  int max_load_steps = 400;
  /// Land on a stable equilibrium. When a solve that did not come from a quasi-Newton warm
  /// re-solve converges, count its unstable directions (StabilityIndex); if there are any, follow
  /// the load path again from the unloaded rod, rejecting (and halving) every load step that lands
  /// on an unstable equilibrium. If no stable path is found, the first (unstable) equilibrium is
  /// returned, converged, with its stability_index > 0. Costs one tangent shot per checked solve.
  bool stable_branch = true;

  bool IsValid(std::string* why) const;
};

struct StaticShootingSummary {
  SolveStatus status = SolveStatus::kNotRun;
  int iterations = 0;   ///< LM plus quasi-Newton iterations, all load steps
  int shots = 0;        ///< integrations from 0 to L (a Jacobian shot counts once)
  int load_steps = 0;   ///< continuation steps taken (0: the direct solve converged)
  double residual = 0;  ///< final dimensionless residual norm
  double wall_time_s = 0;
  bool warm_started = false;
  /// Unstable directions of the returned equilibrium (StabilityIndex): 0 stable, > 0 unstable,
  /// −1 not checked (a quasi-Newton warm re-solve, stable_branch off, follower loads, no
  /// convergence).
  int stability_index = -1;
  int stable_path_steps = 0;  ///< load steps of the stable path search (0: not needed)
  /// The fraction of the loads a continuation that stopped short reached (the state is that
  /// level's); NaN when no continuation stopped short, or the solver does not say.
  double load_fraction = std::numeric_limits<double>::quiet_NaN();
  bool converged() const { return status == SolveStatus::kConverged; }
  /// Counts another solve's work (iterations, shots, load steps, wall time) in this one's: a
  /// result found in several solves reports them all.
  void CountWorkOf(const StaticShootingSummary& other) {
    iterations += other.iterations;
    shots += other.shots;
    load_steps += other.load_steps;
    wall_time_s += other.wall_time_s;
  }
};

/// A cantilever statics solver for one rod model and grid. Construction allocates every buffer;
/// Solve() reuses them and warm-starts from the previous solution (a warm quasi-Newton re-solve
/// allocates nothing; one that falls back to Levenberg–Marquardt or counts its stability does).
class StaticShootingSolver {
 public:
  StaticShootingSolver(const RodModel& model, int num_nodes,
                       const StaticShootingOptions& options = {}, const Actuation& actuation = {});

  /// Solve with the base pose (R_WB of the clamp, p_W of s = 0) and the loads. Warm-starts from
  /// the previous converged solution, if any. Non-finite loads or base give kNonFinite at once; a
  /// base.R that is not a rotation within 1e-6 throws std::invalid_argument. A solve whose
  /// residuals vanish on a shot that ran away (RodState::RanAway: a grid too coarse for the
  /// bend) is kNonFinite too. The state is valid when the status is converged, and holds the
  /// last iterate otherwise.
  StaticShootingSummary Solve(const lie::SE3& base, const StaticLoads& loads);

  /// New actuation (tendon tensions, pressures, jamming states): re-samples the section
  /// properties and the tendon tensions without allocating. The next Solve warm-starts from the
  /// previous solution, which is still the best guess for a small change. Throws
  /// std::invalid_argument for an actuation Actuation::IsValid refuses for this rod (a pushing
  /// tendon, a tendon or chamber it lacks), as the constructor does.
  void SetActuation(const Actuation& actuation);
  const Actuation& actuation() const { return actuation_; }

  /// Path length of each tendon (m) in the last shot, by the RK4 quadrature of |Γ + K × r + r'|
  /// over the grid: after a converged Solve, the tendon lengths of the equilibrium. Zero for
  /// tendons the model does not have.
  const std::array<double, Actuation::kMaxTendons>& tendon_lengths() const {
    return tendon_length_;
  }

  /// d(tip pose)/d(tendon tensions) at the last converged solution (for controllers): column i is
  /// [d p(L)/dτ_i (world, m/N); d θ/dτ_i (rad/N)] with R(L)(τ + dτ) ≈ R(L) Exp(Σ dθ_i dτ_i), the
  /// rotation in the tip body frame. Exact for the discrete model: tangents of the shot in the
  /// tensions and in the unknowns, combined by the implicit function theorem (not finite
  /// differences). Columns past the model's tendons are zero. Allocates nothing. False if there
  /// is no converged solution (or no tendons); std::invalid_argument for a null J, or a base or
  /// loads other than that solve's.
  using TensionJacobian = Eigen::Matrix<double, 6, Actuation::kMaxTendons>;
  bool TipJacobianWrtTensions(const lie::SE3& base, const StaticLoads& loads,
                              TensionJacobian* J) const;

  /// Seed the next Solve with a guess W(0) = [m; n] for the base wrench (base body frame, N·m; N),
  /// taken as if it were the equilibrium under (base, loads): typically the solution of a nearby
  /// model, e.g. the previous length of a growing rod. A Solve at this base then starts from the
  /// guess instead of from the unloaded rod (no Jacobian is reused). If the guess is poor the
  /// solve can fail where a cold one would not: call ResetWarmStart and solve again.
  void WarmStartFrom(const lie::SE3& base, const StaticLoads& loads, const Vec6& base_wrench_B);

  /// Forget the previous solution: the next Solve starts cold.
  void ResetWarmStart() {
    has_solution_ = false;
    has_jacobian_ = false;
  }

  /// Derivative of a shot's state along up to 6 directions (one column each). Rows: d p_W (0–2,
  /// m), d(R_WB e₀), d(R_WB e₁), d(R_WB e₂) (3–11: the columns of R), d m_B (12–14, N·m), d n_B
  /// (15–17, N), all per unit of the direction's parameter.
  using StateTangent = Eigen::Matrix<double, 18, 6>;
  /// One shot for other boundary conditions (columns, buckling modes): integrate from the start
  /// state (base pose, base wrench W(0) = [m; n] in the base body frame, N·m; N) to s = L with
  /// the tangent started at `start`, propagated exactly through RK4 as in ResidualJacobian.
  /// Writes the node states to *record (resized to the grid) and the tangent at every node to
  /// *node_tangents, when not null, and returns the tangent at the tip. Leaves the solver's own
  /// state and warm start alone. Allocates (it is not for hot loops).
  StateTangent ShootTangent(const lie::SE3& base, const StaticLoads& loads,
                            const Vec6& base_wrench_B, const StateTangent& start, RodState* record,
                            std::vector<StateTangent>* node_tangents = nullptr) const;

  /// The same shot over the nodes first … last only (first < last), from the state at node first
  /// (pose `start`, wrench `wrench_B` in its body frame) with the tangent `start_tangent`: writes
  /// nodes first … last of *record (sized to the grid) and of *node_tangents (sized to the
  /// grid), and returns the tangent at node last. For Jacobi fields carried piece by piece along
  /// an equilibrium found by multiple shooting. No tendons (throws std::logic_error).
  StateTangent ShootTangentBetween(int first, int last, const lie::SE3& start,
                                   const Vec6& wrench_B, const StateTangent& start_tangent,
                                   const StaticLoads& loads, RodState* record,
                                   std::vector<StateTangent>* node_tangents) const;

  /// Segment i (nodes i → i + 1) shot again in `parts` RK4 steps from node i's state in `record`
  /// and its tangent in `node_tangents` (those of ShootTangent or ShootTangentBetween): the
  /// parts + 1 states and tangents from s_i to s_{i+1}. A refinement for the stability count
  /// (MorseIndexOfShot). False for rods with tendons.
  bool ShootSegmentRefined(int i, int parts, const StaticLoads& loads, const RodState& record,
                           const std::vector<StateTangent>& node_tangents, RodState* states,
                           std::vector<StateTangent>* tangents) const;

  /// The number of unstable directions of the equilibrium with base wrench W(0) = base_wrench_B
  /// (base body frame, N·m; N) under (base, loads): the Morse index of the second variation of
  /// the potential energy, by a Sturm count of the Jacobi fields along s (conjugate points in
  /// (0, L) plus the negative eigenvalues of the tip stiffness; src/strong/static_stability.cpp).
  /// 0: stable. Counts double roots (a circular rod buckling in two planes) twice. −1 where it is
  /// not defined: follower (body-frame) tip loads, which are not conservative. One tangent shot
  /// plus a 6 × 6 symmetric eigenvalue problem per node; allocates.
  int StabilityIndex(const lie::SE3& base, const StaticLoads& loads,
                     const Vec6& base_wrench_B) const;

  /// The last solve's state (on failure the last iterate's). Before any solve its values are
  /// NaN.
  const RodState& state() const { return state_; }
  int tendon_count() const { return static_cast<int>(model_.tendons.size()); }
  double length() const { return model_.length; }
  const std::vector<double>& grid() const { return grid_; }
  const StaticShootingOptions& options() const { return options_; }
  /// The unknown of the last solve: W(0) = [m; n] in the base body frame (N·m; N).
  Vec6 base_wrench_B() const;

  // Used internally by the solver and by the tests of its Jacobian. One sample per grid node
  // (even index 2i) and per segment midpoint (odd index 2i+1).
  struct Sample {
    Vec6 compliance_diagonal;  ///< diag K(s)⁻¹ (principal-axes sections)
    Vec6 rest_strain;          ///< ξ*(s)
    double mass_per_length;    ///< ρ A, kg/m
    double s = 0.0;            ///< arc length of the sample point, m
    double outer_diameter = 0.0;  ///< m (what the section displaces in a fluid)
    /// The piece of unit length at this sample, for the loads (load.hpp).
    LoadSite Site() const { return {s, 1.0, mass_per_length, outer_diameter}; }
  };
  /// What the tendon strain law needs at a sample point (only for rods with tendons).
  struct TendonStage {
    TendonSample tendons;
    Mat6 stiffness = Mat6::Identity();  ///< K(s)
  };
  /// The dimensionless residual at a dimensionless unknown x (W(0) scaled); fills the state.
  Vec6 Residual(const lie::SE3& base, const StaticLoads& loads, const Vec6& x);
  /// Its Jacobian d residual / d x (6 × 6), the exact derivative of the discrete map (tangents
  /// propagated through RK4 alongside the state). Optionally also the residual.
  Mat6 ResidualJacobian(const lie::SE3& base, const StaticLoads& loads, const Vec6& x,
                        Vec6* residual = nullptr) const;
  /// The same, keeping the shot's node states and tangents: the Levenberg–Marquardt iterations
  /// use it, so the stability check at their solution needs no shot of its own.
  Mat6 ResidualJacobianKeepingTangents(const lie::SE3& base, const StaticLoads& loads,
                                       const Vec6& x, Vec6* residual = nullptr);

 private:
  bool TryQuasiNewton(const lie::SE3& base, const StaticLoads& loads, Vec6* x,
                      StaticShootingSummary* summary);
  bool TryLevenbergMarquardt(const lie::SE3& base, const StaticLoads& loads, double tolerance,
                             Vec6* x, StaticShootingSummary* summary);
  Vec6 RigidGuess(const lie::SE3& base, const StaticLoads& loads) const;
  /// How a solve without continuation ended: converged; with the stored shot at its solution;
  /// by the quasi-Newton warm re-solve.
  struct DirectAttempt {
    bool ok = false;
    bool state_current = false;
    bool via_quasi_newton = false;
  };
  /// The whole load at once, from the start (x_start under start): the quasi-Newton re-solve
  /// when it continues the previous solution, else Levenberg–Marquardt. A result past an
  /// obstacle's surface jumped through it and is refused (*x reset to x_start).
  DirectAttempt SolveDirectly(const lie::SE3& base, const StaticLoads& start,
                              const StaticLoads& loads, const Vec6& x_start, bool from_previous,
                              Vec6* x, StaticShootingSummary* summary);
  /// The residual of the stored shot (state_) under other tip loads: only the tip condition.
  Vec6 StoredShotResidual(const StaticLoads& loads) const;
  /// How FollowLoadPath steps: never more than max_fraction of the path at once; halve a step
  /// that fails (else stop); accept only equilibria without unstable directions; at most
  /// max_steps steps.
  struct LoadPath {
    double max_fraction = 1.0;
    bool halve_on_failure = true;
    bool require_stable = false;
    int max_steps = 1;
  };
  /// Natural-parameter continuation along loads(μ) = start + μ (loads − start), μ: 0 → 1, from
  /// the solution x_start at μ = 0, with a secant predictor and Levenberg–Marquardt at each μ;
  /// a step doubles after a success. Writes the last accepted unknowns to *x and the number of
  /// steps to *steps; true when μ = 1 was reached.
  bool FollowLoadPath(const lie::SE3& base, const StaticLoads& start, const StaticLoads& loads,
                      const Vec6& x_start, const LoadPath& path, Vec6* x, int* steps,
                      StaticShootingSummary* summary, double* reached_fraction = nullptr);
  /// The node positions of the shot at x under `loads` (world, m; records state_).
  std::vector<Vec3> ShotPositions(const lie::SE3& base, const StaticLoads& loads, const Vec6& x);
  /// False when the step from the shot (x_from, loads_from) to (x, loads) passes a node into an
  /// obstacle's core (obstacle_core.hpp): a solution the surfaces would have held back. True
  /// without obstacles, with no shot.
  bool HeldBack(const lie::SE3& base, const StaticLoads& loads_from, const Vec6& x_from,
                const StaticLoads& loads, const Vec6& x);
  /// Past a critical load the converged equilibrium may be unstable: if it is, replaces *x by
  /// the stable equilibrium the path from the unloaded rod leads to, when that path exists.
  /// False when the equilibrium was stable (the stored shot is still that of *x).
  bool KeepStableBranch(const lie::SE3& base, const StaticLoads& loads, double max_fraction,
                        Vec6* x, StaticShootingSummary* summary);
  /// StabilityIndex at the unknown x just solved for: from the kept Jacobian shot when it was
  /// taken at x under (base, loads), else with a shot of its own.
  int IndexAfterSolve(const lie::SE3& base, const StaticLoads& loads, const Vec6& x) const;
  int StabilityIndexFromShot(const StaticLoads& loads, const RodState& record,
                             const std::vector<StateTangent>& nodes) const;
  void SampleSections();
  /// The sample of the section law at s under the current actuation.
  Sample SampleAt(double s) const;
  /// The tangent shot over `grid` with its `samples` from the state (start, wrench_B) and
  /// tangent start_tangent: the node states into *piece, the node tangents into *tangents; the
  /// tangent at the end.
  StateTangent ShootTangentOn(const std::vector<double>& grid, const std::vector<Sample>& samples,
                              const lie::SE3& start, const Vec6& wrench_B,
                              const StateTangent& start_tangent, const StaticLoads& loads,
                              RodState* piece, std::vector<StateTangent>* tangents) const;

  RodModel model_;
  StaticShootingOptions options_;
  Actuation actuation_;
  std::vector<double> grid_;
  std::vector<double> sample_points_;  ///< s of samples_ (m): SampleSections allocates nothing
  std::vector<Sample> samples_;
  std::vector<TendonStage> tendon_stages_;  ///< parallel to samples_; empty without tendons
  std::array<double, Actuation::kMaxTendons> tendon_length_{};
  Vec6 scale_;  ///< W = scale ⊙ x: [EI/L ×3, EI/L² ×3]
  RodState state_;
  std::vector<Vec3> rest_position_B_;  ///< rest shape in the base body frame, for guesses
  std::vector<Mat3> rest_rotation_B_;

  bool has_solution_ = false;
  bool state_is_solution_ = false;  ///< state_ holds the shot of x_ at solved_base_/solved_loads_
  Vec6 x_ = Vec6::Zero();
  lie::SE3 solved_base_;
  StaticLoads solved_loads_;
  Mat6 jacobian_ = Mat6::Identity();  ///< d r / d x at the last solution
  bool has_jacobian_ = false;
  // The last ResidualJacobianKeepingTangents shot: at kept_x_ under kept_base_, kept_loads_.
  RodState kept_record_;
  std::vector<StateTangent> kept_tangents_;
  Vec6 kept_x_ = Vec6::Zero();
  lie::SE3 kept_base_;
  StaticLoads kept_loads_;
  bool has_kept_ = false;
};

}  // namespace cosserat
