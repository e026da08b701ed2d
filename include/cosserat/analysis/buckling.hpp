#pragma once
/// \file
/// Buckling of rods and columns: the critical load along a load path, the buckling mode, and the
/// post-buckled branch (docs/buckling.md).
///
/// Statics is followed along loads(λ) = fixed + λ · per_unit with warm starts (ColumnSolver).
/// An equilibrium stops being stable where the linearised boundary-value problem gets a
/// non-trivial solution: exactly where the 6 × 6 shooting Jacobian J = d r / d u is singular (a
/// conjugate point). The scan watches σ_min(J) and the sign of det J; the critical λ is refined
/// by bisection on det J (a simple crossing) or by golden-section search on σ_min (a double one,
/// as for a rod symmetric about its axis, where det J touches zero without changing sign). The
/// mode is the null vector of J propagated along s by the shot's tangent.

#include <array>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "cosserat/analysis/column.hpp"

namespace cosserat {

/// loads(λ) = fixed + λ · per_unit, tendon tensions(λ) = fixed_actuation + λ · tension_per_unit,
/// inflation pressure(λ) = fixed_actuation.pressure + λ · pressure_per_unit.
/// λ carries the unit of the load: N for a tip force of unit direction, N/m for a distributed
/// force, m/s² for gravity, N for tendon tension, Pa for pressure.
struct LoadPath {
  StaticLoads fixed;     ///< applied whatever λ; its tip-load frames must match per_unit's
  StaticLoads per_unit;  ///< the load per unit λ
  Actuation fixed_actuation;
  std::array<double, Actuation::kMaxTendons> tension_per_unit{};  ///< N per unit λ
  /// Pa per unit λ. Pressure acts through the section (PressureModulusSection, InflatedTube-
  /// Section: EI = E_eff(p) I), not as a load: raising it stiffens. A negative value follows a
  /// pressure drop (PressureDrop), along which a column under a fixed load loses stability.
  double pressure_per_unit = 0.0;

  /// A tip force λ · direction (normalised): dead (kWorld) or a follower (kBody).
  static LoadPath TipForce(const Vec3& direction, LoadFrame frame = LoadFrame::kWorld);
  /// The inflation pressure falls from `initial_pressure` (Pa) as p(λ) = initial_pressure − λ
  /// (λ in Pa) under the fixed `loads` (e.g. a dead axial tip force). The critical λ gives the
  /// lowest pressure at which the column still stands: p_cr = initial_pressure − λ_cr. Search up
  /// to lambda_max ≤ initial_pressure (pressure ≥ 0).
  static LoadPath PressureDrop(double initial_pressure, const StaticLoads& loads);
  StaticLoads LoadsAt(double lambda) const;
  Actuation ActuationAt(double lambda) const;
  /// True if λ changes the actuation (tendon tensions or pressure), not only the loads.
  bool has_actuation() const;
};

struct BucklingOptions {
  /// The largest λ searched (load units, see LoadPath).
  double lambda_max = 1.0;
  /// The scan takes this many equal steps from 0 to lambda_max (a step that fails to converge is
  /// halved, at most 10 times). Two critical loads closer than a step apart may be seen as one.
  int scan_steps = 40;
  /// Refinement stops when the bracket is narrower than this fraction of λ_cr.
  double lambda_tolerance = 1e-11;
  /// A minimum of σ_min(J) counts as a singular point when σ_min there is below this fraction of
  /// σ_min at λ = 0 (otherwise the scan goes on).
  double singular_threshold = 1e-6;
  /// The static solves: tolerance and Newton iterations per solve.
  StaticShootingOptions solver;
  /// The largest exponent ∫ sqrt(T/EI) ds of the axial tension T along a solved equilibrium
  /// (SingleShootingExponent in statics) the search trusts: the single shot's Jacobi fields grow
  /// like its exponential, and a solve past it counts as failed (the path ends there; a rod in
  /// such tension is BucklingInPieces's). 10, the static solvers' limit for one shot.
  double max_shot_exponent = 10.0;
  /// Called after every accepted point of the scan with its λ and lambda_max; may be empty (a
  /// progress line for a long search).
  std::function<void(double lambda, double lambda_max)> progress;

  bool IsValid(std::string* why) const;
};

/// The buckling mode along s, scaled so that max_s |δp(s)| = 1 m (its sign: the largest
/// displacement component positive). δθ is the rotation in the body frame, R⁻¹ δR = δθ^.
struct BucklingMode {
  std::vector<double> s;             ///< node arc lengths, m
  std::vector<Vec3> displacement_W;  ///< δp(s), world frame, m
  std::vector<Vec3> rotation_B;      ///< δθ(s), body frame, rad per m of displacement
  std::vector<Vec3> curvature_B;     ///< δK(s), body frame, 1/m per m (the larger side at a
                                     ///< stiffness jump)
  double s_max_curvature = 0;        ///< where |δK₁,₂| is largest (the first such node), m
  Vec6 unknowns = Vec6::Zero();      ///< the null vector of J in the unknowns (unit norm)
  bool double_root = false;          ///< J has a 2-D null space (any plane buckles alike)
};

/// The mode from the first-order change t[i] of the equilibrium `state` at every node (18 rows as
/// in ColumnSolver::StateTangent: d p_W, the columns of d R, d m_B, d n_B) along the null vector
/// v of the tip conditions (unit, in the unknowns): displacement, rotation, curvature (from the
/// sections' compliance under `actuation`), scaled to max |δp| = 1 m, its largest displacement
/// component positive, and `unknowns` = ±v alike.
BucklingMode ModeFromPerturbation(const RodModel& model, const Actuation& actuation,
                                  const RodState& state,
                                  const std::vector<Eigen::Matrix<double, 18, 1>>& t,
                                  const Vec6& v, bool double_root);

enum class BucklingStatus {
  kNotRun,
  kFound,       ///< a singular point of J on [0, lambda_max], refined to lambda_tolerance.
  kNotFound,    ///< the path reached lambda_max with J regular all along.
  kPathFailed,  ///< a static solve failed even after 10 step halvings (a fold of the path, or a
                ///< solver failure); critical_load is NaN, lambda_reached says how far it got.
  /// The fixed loads alone pass a singular point of J (at preload_critical_fraction of them): the
  /// equilibrium they load is past a critical point, and no load on top of them is its critical
  /// load (the scan would find a higher one). critical_load is NaN.
  kPreloadPastCritical,
};

/// "found", "not_found", "path_failed", "not_run".
const char* ToString(BucklingStatus status);

struct BucklingSummary {
  BucklingStatus status = BucklingStatus::kNotRun;
  double critical_load = NAN;          ///< λ_cr (load units); NaN unless found
  /// The width of the bracket the refinement reached below critical_load (load units): below
  /// lambda_tolerance · λ_cr, unless the solves near the root failed first (BucklingInPieces).
  double critical_load_bracket = 0;
  double lambda_reached = 0;           ///< the last λ of the path where statics converged
  double sigma_min_ratio = NAN;        ///< σ_min(J(λ_cr)) / σ_min(J(0))
  BucklingMode mode;                   ///< valid when found
  std::vector<double> scan_lambda;     ///< the scan: λ …
  std::vector<double> scan_sigma_min;  ///< … and σ_min(J) there
  int solves = 0;                      ///< static solves
  double wall_time_s = 0;
  /// With kPreloadPastCritical: the fraction of the fixed loads at which J turned singular.
  double preload_critical_fraction = NAN;
  /// With kPathFailed: the path ended where the rod's tension passed max_shot_exponent.
  bool beyond_single_shot = false;
  bool found() const { return status == BucklingStatus::kFound; }
};

/// Ends a search: its status, and the wall time since t0 in *out; returns *out.
BucklingSummary FinishSearch(BucklingStatus status, std::chrono::steady_clock::time_point t0,
                             BucklingSummary* out);

/// Buckling of one rod under one load path. Construction allocates the column solver.
class BucklingAnalysis {
 public:
  BucklingAnalysis(const RodModel& model, int num_nodes, ColumnEnds ends, const lie::SE3& base,
                   const LoadPath& path, const BucklingOptions& options = {});

  /// Scan, detect, refine, and extract the mode. Leaves state() at the pre-buckled equilibrium
  /// at λ_cr (or at the last λ reached).
  BucklingSummary FindCriticalLoad();

  /// The equilibrium on the post-buckled branch at λ > λ_cr (after a found FindCriticalLoad):
  /// branch switching at λ_cr along the mode, continuation in the mode amplitude
  /// η = v · (u − u_cr) with λ free (a bordered Newton system, regular through the
  /// bifurcation), then Newton at λ. The branch is the one with η > 0 (the mode's sign).
  /// state() holds the solution.
  ColumnSummary SolvePostBuckled(double lambda);

  const RodState& state() const { return column_.state(); }
  const ColumnSolver& column() const { return column_; }
  const LoadPath& path() const { return path_; }

 private:
  ColumnSummary SolveAt(double lambda);
  Vec6 ResidualAt(double lambda, const Vec6& u, Mat6* J, RodState* record = nullptr,
                  std::vector<ColumnSolver::StateTangent>* tangents = nullptr);
  /// σ_min(J), sign(det J) and the stability index (−1: not defined) at the equilibrium last
  /// solved, from one tangent shot.
  void Singularity(double lambda, double* sigma_min, double* det_sign, int* index);
  BucklingMode ExtractMode(double lambda, const Vec6& v, bool double_root) const;
  /// The equilibrium at λ = 0 from the unloaded rod, the fixed loads applied in 1, 4, 16 or 64
  /// equal steps until all converge (false if none does) and, with require_stable, land on an
  /// equilibrium whose stability index is not positive (if none does, the first that converges);
  /// counts the solves.
  bool SolveFixedLoads(bool require_stable, int* solves);
  /// The fixed loads scaled from 0 to 1.25 of themselves (λ = 0), scanned from the unloaded rod
  /// as the load path is: the first share at which J turns singular (below 1: the preload is
  /// past it); NaN when J stays regular or a solve fails (the solve of the whole fixed loads
  /// then decides).
  double PreloadCriticalFraction(BucklingSummary* out);
  /// λ_cr, the pre-buckled equilibrium there (solved from `guess`), its null vector and the
  /// mode, into the members and *out; sigma0 = σ_min(J) at λ = 0.
  void SetCriticalPoint(double lambda, const Vec6& guess, double sigma0, BucklingSummary* out);
  /// The bordered Newton iteration of SolvePostBuckled at mode amplitude η = v · (u − u_cr),
  /// λ free: true when |r| and the amplitude condition meet the solver's tolerance.
  bool BorderedNewton(double eta, Vec6* u, double* lambda);

  ColumnSolver column_;
  RodModel model_;
  lie::SE3 base_;
  LoadPath path_;
  BucklingOptions options_;
  double applied_lambda_ = 0;  ///< λ of the actuation currently set in column_
  bool found_ = false;
  bool beyond_single_shot_ = false;  ///< a solve of this search passed max_shot_exponent
  double lambda_cr_ = NAN;
  Vec6 u_cr_ = Vec6::Zero();
  Vec6 v_cr_ = Vec6::Zero();
};

}  // namespace cosserat
