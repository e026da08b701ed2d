#pragma once
/// \file
/// Dynamics of a cantilevered rod on the SE(3) strong form: BDF2 in time, shooting in s
/// (FD notes 2025, eqs. 19–28). Built once, then Step() advances one time step without allocating,
/// for use inside a controller.
///
/// Per step, with c0, c1, c2 the BDF2 weights (eq. 23, variable-step form) and the history terms
/// ξʰ = c1 ξ(t−h₁) + c2 ξ(t−h₁−h₂), Vʰ likewise (eqs. 21–22), integrate from s = 0 to L with an
/// explicit Runge–Kutta scheme (RK4 across pairs of segments, RK4 or Heun; spatial_scheme.hpp):
///   p' = R Γ,  R' = R K̂,
///   V' = ξ_t + ad_V ξ                  (eq. 25; ω' = K_t + ω × K, v' = Γ_t + ω × Γ + v × K)
///   m' = m × K + n × Γ + J ω_t + ω × J ω,
///   n_W' = −f_W + ρA a_W,  n = Rᵀ n_W                 (eq. 26 for W = [m; n] = −Λ)
/// where a_W is the BDF2 rate of the world velocity R v (continuous limit R (v_t + ω × v)); the
/// force is carried in the world frame so that linear momentum is conserved to round-off.
///   ξ = (K + c0 D)⁻¹ (W + K ξ* − D ξʰ),  ξ_t = c0 ξ + ξʰ,  V_t = c0 V + Vʰ   (eq. 27)
/// with g(0), V(0) prescribed and the unknown W(0) chosen so that W(L) is the tip wrench (eq. 28).
/// History is kept at the scheme's stage points, so a rod at rest in equilibrium stays there
/// exactly.

#include <Eigen/Dense>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/state/solve_status.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"
#include "cosserat/strong/rod_integrals.hpp"
#include "cosserat/strong/secant_filter.hpp"
#include "cosserat/strong/sequence_predictor.hpp"
#include "cosserat/strong/spatial_scheme.hpp"

namespace cosserat {

/// End conditions (FD notes 2025, eqs. 28 and 29).
enum class EndConditions {
  kCantilever,  ///< g(0), V(0) prescribed; unknown W(0); W(L) = tip wrench
  kFreeFree,    ///< W(0) = −base wrench, W(L) = tip wrench; unknown V(0), g(0) follows from it
};

/// How the tip (s = L) of a cantilevered rod is held during a step. Free: the tip wrench
/// condition (eq. 28). Otherwise the tip is joined to a frame that moves with the step
/// (StepInput::tip_pose: a body of an assembly, a moving anchor), and the joint's conditions
/// replace the wrench condition:
///   kClamped      the tip's frame is tip_pose;
///   kTorsionFree  the tip's position and tangent (body z) are tip_pose's, no moment about it;
///   kPinned       the tip's position is tip_pose's, no moment (a ball joint);
///   kGuidedClamped, kGuidedPinned  a column's tip: it slides along the axis tip_pose.R e₃
///                 through tip_pose.p (its displacement across it held), the force along it the
///                 loads' dead tip force's, and its frame tip_pose.R (clamped) or no moment.
/// The holder takes the loads' tip wrench and a tip body (Bdf2Options::tip_mass): they are not
/// used with a held tip, but for the guided tips' axial force (dead, world frame).
enum class TipHold { kFree, kClamped, kTorsionFree, kPinned, kGuidedClamped, kGuidedPinned };

struct Bdf2Options {
  double dt = 2e-3;  ///< time step, s
  /// The first step of a run (after InitializeAtRest). Backward Euler (the default) keeps a run
  /// whose loads jump at t = 0 (a release) second order: BDF2 over the rest history would
  /// difference the jump in acceleration and leave a velocity error of a third of it times dt.
  /// BDF2 over the rest history instead conserves an impulse applied during the first step
  /// exactly (a backward Euler start followed by BDF2 counts it 1.5 times).
  enum class FirstStep { kBackwardEuler, kBdf2OverRest };
  FirstStep first_step = FirstStep::kBackwardEuler;
  EndConditions ends = EndConditions::kCantilever;
  /// Convergence of each step: ‖r‖₂ < tolerance for the tip residual made dimensionless by
  /// EI/L (moments) and EI/L² (forces), as in statics.
  double tolerance = 1e-10;
  /// Newton-type iterations per pass (a hard cap on each pass: Step() is deterministic). An
  /// attempt is a secant-Newton pass and, if that fails, a Levenberg–Marquardt pass from its
  /// best point: at most 2 max_iterations + 1 iterations (41 at 20). A step's whole work is
  /// bounded by the attempts: a failed one is retried in more pieces (automatic pieces, up to
  /// 256) and then as halves, up to max_halvings deep, each sub-step with its own attempts; a
  /// bad tick then costs ~100× a good one (196 iterations, 0.1 s on a tendon robot pushed by
  /// 1 kN), and the pieces it adds stay for the next 10 or more steps taken whole
  /// (DropUnneededPieces). For a hard bound per tick: max_halvings = 0 and shooting_segments
  /// fixed (one attempt on one shot plan), with a failed step handled by the caller (Restore of
  /// the last good Snapshot). A problem file's solver.max_iterations (default 50)
  /// sets it for the CLI and Python (run::DynamicsOptions); a stepper built from these defaults
  /// gives up sooner on a hard step than they do.
  int max_iterations = 20;
  /// When an attempt fails, retry as two steps of half the size, up to this depth.
  int max_halvings = 3;
  /// A rigid body fixed at the tip, centred on the tip node: mass (kg) and principal moments of
  /// inertia in the tip body frame (kg·m²). It feels gravity. Zero: no tip body.
  double tip_mass = 0.0;
  Vec3 tip_inertia_B = Vec3::Zero();
  /// Multiple shooting: the rod is shot in this many pieces of about equal node count, with
  /// the 18 state components (pose, wrench, twist) at each interior junction as extra unknowns
  /// and their continuity as extra residuals (bdf2_multiple_shooting.cpp). The discrete
  /// equations, and so the solution, are those of single shooting (1, the default); what
  /// changes is the conditioning. One shot amplifies an error in W(0) by about e^{λL} with
  /// λ ∝ dt^(-1/2) (the BDF2 inertia c0² ρA against EI), so small dt (or stiff, long rods) need
  /// pieces: for the steel peer rod, dt = 0.5 ms gives e^17 and single shooting fails, while 8
  /// pieces see e^2 each. Costs a finite-difference Jacobian of size 6 + 18 (pieces − 1),
  /// reused across steps: for reference runs, not for the real-time path. Steps are solved by
  /// Newton only (no Levenberg–Marquardt fallback; a failure halves the step as usual).
  /// 0 (the default): the stepper chooses. It starts with one piece when λL ≤ 10 (single
  /// shooting's safe range) and SuggestedShootingSegments(λL) above (shooting_exponent.hpp), and
  /// when a step fails it doubles the pieces (up to 256, and the shot's steps) before it halves
  /// the step. StepSummary::shooting_segments reports the pieces of each step.
  int shooting_segments = 0;
  /// Explicit scheme of the shot in s (spatial_scheme.hpp): RK4 across pairs of segments (the
  /// default: order 4 at two stage evaluations per segment where the pair is short against the
  /// step's exponent, plain RK4 elsewhere), RK4 on every segment, or Heun (order 2, as BDF2 in
  /// time, at two). The BDF2 history lives at the scheme's stage points, so a stepper keeps its
  /// scheme.
  SpatialScheme spatial_scheme = SpatialScheme::kRk4Pairs;

  bool IsValid(std::string* why) const;
};

/// What drives the rod during one step; values at the end of the step.
struct StepInput {
  /// Cantilever: g(0, t), the base pose in the world. Free-free: used only by InitializeAtRest
  /// (the pose of the s = 0 end at t = 0); afterwards the pose is part of the state.
  lie::SE3 base_pose;
  /// Cantilever: V(0, t) = [ω; v], body frame (rad/s; m/s). An input, not derived from the
  /// change of base_pose: a clamp that moves must give its twist too, or the rod's base node is
  /// dragged along with zero velocity (every step still converges, to the wrong motion).
  Vec6 base_twist_B = Vec6::Zero();
  Vec6 base_wrench_B = Vec6::Zero();  ///< free-free: wrench applied to the s = 0 end, body frame
  TipHold tip_hold = TipHold::kFree;  ///< cantilever only
  lie::SE3 tip_pose;                  ///< the frame a held tip is joined to, world
  StaticLoads loads;                  ///< gravity, distributed force, tip force and moment
  /// Tendon tensions (used when the model has tendons), pressure and jamming states (read by the
  /// section profile). A change of the section-related fields re-samples the sections at the
  /// start of the step (no allocation); the history strains carry over, so the shape is
  /// continuous across a switch.
  Actuation actuation;
};

struct StepSummary {
  SolveStatus status = SolveStatus::kNotRun;
  int iterations = 0;  ///< Newton-type iterations, all attempts
  int shots = 0;       ///< integrations from 0 to L
  int jacobians = 0;   ///< of which with the exact Jacobian (each costs about ten plain shots)
  int halvings = 0;    ///< deepest step halving used (0: the step went through whole)
  int shooting_segments = 1;  ///< pieces the step was shot in (Bdf2Options::shooting_segments)
  double residual = 0.0;
  double wall_time_s = 0.0;
  bool converged() const { return status == SolveStatus::kConverged; }
};

class Bdf2ShootingStepper {
 public:
  Bdf2ShootingStepper(const RodModel& model, int num_nodes, const Bdf2Options& options = {});

  /// Puts the rod at rest in static equilibrium under `input` (its base twist is ignored) at
  /// time t = 0, with a history that says it has been at rest. Cantilever: the solve starts
  /// from `base_wrench_B` (W(0), body frame) when given, else from the wrench that carries the
  /// loads as a rigid body. With automatic pieces, the equilibrium's tension may ask for more
  /// pieces for the steps (SingleShootingExponent with the state); only then does it allocate.
  /// NaN or Inf in the input (InputIsFinite) is the status non_finite, and changes nothing. A
  /// start that fails otherwise (no equilibrium, or one whose shot ran away: non_finite, see
  /// RodState::RanAway) ends the run before it: Step() is not_run until a start converges or a
  /// Snapshot is restored. From the rigid-body guess, under large loads the solve may converge on
  /// another equilibrium than the one the loads grow along (a 1 m steel wire pushed sideways by
  /// 2 N, FL²/EI = 13, came back looped, and unstable): a cantilever starts more surely from a
  /// StaticShootingSolver's state (the overload below), as the CLI starts.
  StepSummary InitializeAtRest(const StepInput& input, const Vec6* base_wrench_B = nullptr);

  /// As above (cantilever), from an equilibrium found elsewhere on this grid, such as a statics
  /// solver's state with the same nodes: its base wrench starts the solve, and its nodes start
  /// the junctions of multiple shooting. With automatic pieces the stepper shoots this statics
  /// in pieces when the state's tension makes one shot from the base ill-conditioned (the
  /// exponent of SingleShootingExponent with the state above 10): a taut wire, a hanging pipe,
  /// a payload on a wire, where a single shot from a rigid-body guess may settle on a looped
  /// equilibrium. Throws std::invalid_argument if `equilibrium` is not on this grid.
  StepSummary InitializeAtRest(const StepInput& input, const RodState& equilibrium);

  /// Advances by options().dt to the state under `input`. No heap allocation, except in a
  /// step that changes the automatic multiple-shooting pieces (adds them on a failure, halves
  /// them back after 10 steps taken whole, or up to 160 when such drops failed before:
  /// DropUnneededPieces). When a step
  /// fails even after halving, the status says why and time() and state() are those of the last
  /// (sub-)step that converged. NaN or Inf in the input (InputIsFinite) is the status non_finite
  /// (nothing moves); an actuation Actuation::IsValid refuses for this rod (a pushing tendon, a
  /// tendon or chamber it lacks), or a base (or held tip) rotation that is not one within 1e-6
  /// (lie::RequireRotation), throws std::invalid_argument, as InitializeAtRest does. Before a
  /// converged InitializeAtRest (or a Restore) there is no run to step: status not_run, nothing
  /// moves. A step whose shot ran away (RodState::RanAway) is not taken: non_finite, no pieces
  /// added nor halving tried (only a finer grid follows such a bend).
  StepSummary Step(const StepInput& input);
  /// Throws std::invalid_argument for the inputs Step refuses (its actuation or poses); NaN and
  /// Inf pass (Step reports them as a status). For callers that check a batch before any step.
  void RequireValidInput(const StepInput& input) const {
    if (input.actuation.AllFinite()) RequireActuation(input.actuation);
    if (InputIsFinite(input)) RequirePoses(input);
  }
  /// Whether the input's fields these ends read (a held tip's pose, a free base's wrench) are
  /// finite: else Step and InitializeAtRest return non_finite and change nothing.
  bool InputIsFinite(const StepInput& input) const;

  double time() const { return run_.time; }
  /// The last accepted step's state (the rest state after InitializeAtRest). Before a run
  /// starts its values are NaN: read it once InitializeAtRest has converged.
  const RodState& state() const { return run_.state; }
  const Bdf2Options& options() const { return options_; }
  const std::vector<double>& grid() const { return grid_; }
  /// The steps of the shot in s: the grid's segments, less one for each pair kRk4Pairs forms.
  int shot_steps() const {
    return static_cast<int>(grid_.size()) - 1 -
           static_cast<int>(std::count(pair_start_.begin(), pair_start_.end(), 1));
  }
  /// The automatic choice of multiple-shooting pieces for the rod now: PiecesFor the shot's
  /// exponent with dt, the actuation and the state's tension.
  int ChosenPieces() const;
  /// The current state at the stage points of the spatial scheme with its quadrature weights:
  /// what the free functions of rod_integrals.hpp (energy, momentum, mass) integrate.
  RodQuadrature QuadraturePoints() const;
  /// Shorthands for those integrals of the current state (the rod only: a tip body's energy and
  /// momentum are not included).
  RodEnergy Energy(const StaticLoads& loads) const {
    return cosserat::Energy(QuadraturePoints(), loads);
  }
  RodMomentum Momentum() const { return cosserat::Momentum(QuadraturePoints()); }
  double Mass() const { return cosserat::Mass(QuadraturePoints()); }
  Vec3 CentreOfMass_W() const { return cosserat::CentreOfMass_W(QuadraturePoints()); }

  /// The whole steps taken before the pieces a failure added are first halved back
  /// (DropUnneededPieces), and the longest such wait, after drops that failed in a row.
  static constexpr int kFirstDropWait = 10, kLongestDropWait = 160;
  /// The most pieces the automatic choice takes (λL/5 of them; doubled on a failure). The
  /// junctions' Jacobian is block-banded, so a step's cost grows only linearly with them: a 1 km
  /// drill string hanging in tension (λL ≈ 480) needs about 96, and failed at 32.
  static constexpr int kMostAutomaticPieces = 256;

  /// Everything Step() needs to continue a run. Save() allocates; Restore() into a stepper of the
  /// same model and grid does not, and throws std::invalid_argument for a snapshot taken before
  /// InitializeAtRest or from a stepper of another model, grid or end conditions.
  struct Snapshot {
    double time = 0;
    double last_dt = 0;                   ///< size of the last accepted step (0 before the first)
    SequencePredictor unknowns{2, true};  ///< the converged unknowns of the last steps
    SecantFilter jacobian_filter;         ///< the shooting Jacobian, tracked across steps
    double jacobian_c0 = -1.0;            ///< the c0 the Jacobian was computed for; −1: none
    int steps_taken = 0;
    /// Steps taken whole (no halving, no added piece) since the automatic pieces last changed.
    int whole_steps = 0;
    /// The whole steps DropUnneededPieces waits for before it halves the pieces a failure added:
    /// kFirstDropWait, doubled (up to kLongestDropWait) each time pieces it dropped had to be
    /// added back, and back to kFirstDropWait once a drop has held for a whole wait.
    int drop_wait = kFirstDropWait;
    bool dropped_pieces = false;  ///< the pieces' last change was a drop that has not yet held
    // Accepted values at the stages of each step of the shot (index step_slot_[i] + j for the
    // step from node i), one and two steps back, and at the tip node.
    std::vector<Vec6> strain1, strain2, twist1, twist2;
    std::vector<Vec3> position1;
    std::vector<Mat3> rotation1;
    std::vector<Vec3> velocity_W1, velocity_W2;  ///< R v
    Vec6 tip_strain1 = Vec6::Zero(), tip_strain2 = Vec6::Zero();
    Vec6 tip_twist1 = Vec6::Zero(), tip_twist2 = Vec6::Zero();
    lie::SE3 base1, base2;  ///< pose of the s = 0 end one and two steps back
    /// Multiple shooting: the junction unknowns of the last step (its change of the junction
    /// states, the next step's first guess); empty for single shooting.
    Eigen::VectorXd junction_unknowns;
    /// Multiple shooting: the LU factors of the Jacobian the next step starts from (rows
    /// [mismatch of junction 0, 1, …; tip], columns [x; z of junction 0, 1, …]; block-banded, 29
    /// sub- and 23 super-diagonals, O(pieces) to factor), and the c0 they are for (−1: none). In
    /// the snapshot, so that a restored run repeats the original bit for bit.
    BandedMatrix junction_factors;
    double junction_factors_c0 = -1.0;
    StepInput last_input;  ///< input of the last accepted (sub-)step, for sub-step blending
    RodState state;        ///< the last accepted step
    /// What Restore() checks: a run exists (InitializeAtRest was called), and the stepper it
    /// came from had the same rod, grid and end conditions (a hash of the grid, the unactuated
    /// sections at its nodes, the tendons' routes and anchors, the chambers, the ends and the
    /// spatial scheme).
    bool initialized = false;
    std::uint64_t model_fingerprint = 0;
  };
  /// Growth at the tip (eversion): continues the run on `longer`, a model of the same rod whose
  /// length is larger and whose sections agree on [0, L_old]. The old grid nodes keep their
  /// place in s and their history (material behind the tip stays where it is); `new_segments`
  /// segments (plus any breakpoints of `longer` there) are appended, with the history of the old
  /// tip (new material leaves the tip moving with it). Allocates: not for the real-time path.
  void Grow(const RodModel& longer, int new_segments);

  Snapshot Save() const { return run_; }
  void Restore(const Snapshot& snapshot);
  /// Throws what Restore(snapshot) would throw, and changes nothing.
  void RequireRestorable(const Snapshot& snapshot) const;

  // Per-stage section data (cosserat_rhs.hpp); public for the implementation's helpers.
  using Sample = rhs::SectionSample;
  struct Coefficients {
    double c0 = 0, c1 = 0, c2 = 0;
  };
  /// The BDF2 weights of a step h after a step h_prev (0: the first step of a run), as Step()
  /// uses them: y' ≈ c0 y_n + c1 y_{n−1} + c2 y_{n−2}. For what moves with the rod (a body
  /// joined to it) and must see the same rates.
  static Coefficients Weights(double h, double h_prev, Bdf2Options::FirstStep first);
  /// One shot: the dimensionless tip residual for the dimensionless unknown x (W(0) = scale ⊙ x),
  /// with BDF2 weights c, or the static equations when statics is true. Writes the trial state
  /// and the stage values. With J, also d r / d x: the exact derivative of the discrete shot
  /// (tangent propagation through the spatial scheme), at about ten times the cost; for
  /// free-free it drops the O(dt) change of J_r in the base pose, so it is close but not exact.
  /// Used by the solver and its tests.
  Vec6 Residual(const StepInput& input, const Coefficients& c, bool statics, const Vec6& x,
                Mat6* J = nullptr);

 private:
  class Shot;  ///< one shot in progress (bdf2_shot.cpp)
  bool Attempt(const StepInput& input, double h, StepSummary* summary);
  bool AttemptInterval(const StepInput& from, const StepInput& to, double h, int depth,
                       StepSummary* summary);
  /// Solves one step of size h (statics: h unused) for the unknowns; on success they are in
  /// solved_unknowns_ and the trial state holds the shot.
  bool SolveStep(const StepInput& input, const Coefficients& c, double h, bool statics,
                 StepSummary* summary);
  /// SolveStep's fast path: Newton with the secant filter's Jacobian from *x; on failure *x is
  /// the best point reached and *r its residual.
  bool SolveStepBySecantNewton(const StepInput& input, const Coefficients& c, bool statics, Vec6* x,
                               Vec6* r, StepSummary* summary);
  /// The residual at x with the exact Jacobian, which restarts *filter (one shot, one Jacobian).
  Vec6 RestartWithExactJacobian(const StepInput& input, const Coefficients& c, bool statics,
                                const Vec6& x, SecantFilter* filter, StepSummary* summary);
  /// An exact Newton step dx from x (residual norm `norm`) that overshot: halves it up to four
  /// times until the residual decreases sufficiently; true with *dx, *r_new the accepted step.
  bool BacktrackExactStep(const StepInput& input, const Coefficients& c, bool statics,
                          const Vec6& x, double norm, Vec6* dx, Vec6* r_new,
                          StepSummary* summary);
  /// SolveStep's fallback: Levenberg–Marquardt with the exact Jacobian from x_start.
  bool SolveStepByLevenbergMarquardt(const StepInput& input, const Coefficients& c, bool statics,
                                     const Vec6& x_start, StepSummary* summary);
  /// SolveStep for shooting_segments > 1 (bdf2_multiple_shooting.cpp). In statics the junctions
  /// start from run_.state, which the caller has set to a guess of the equilibrium.
  bool SolveStepMultiple(const StepInput& input, const Coefficients& c, double h, bool statics,
                         StepSummary* summary);
  /// Multiple shooting's residual [junction mismatches; tip (6)] at the unknowns X = [x (6); z];
  /// false if not finite.
  bool MultipleResidual(const StepInput& input, const Coefficients& c, bool statics,
                        const Eigen::VectorXd& X, Eigen::VectorXd* R, StepSummary* summary);
  /// Statics in pieces: up to kChordSteps chord steps with the current factors from ms_x_new_
  /// (a full Newton step that raised the residual); true, with ms_x_new_ and ms_r_new_ moved
  /// there, once one brings the residual below `norm`. A rod held in tension needs them: its
  /// tip position residual (over L) is tiny against the junctions' rotation rows a good step
  /// disturbs (1.7e-6 → 1.8e-4 for a steel wire whose held tip moved 1 µm).
  bool ChordStepsBelow(const StepInput& input, const Coefficients& c, double norm,
                       StepSummary* summary);
  /// Both InitializeAtRest: `equilibrium`, when given, has been checked to be on the grid.
  StepSummary InitializeAtRestFrom(const StepInput& input, const Vec6* base_wrench_B,
                                   const RodState* equilibrium);
  /// InitializeAtRest's solve (cantilever: from base_wrench_B or the rigid-body guess, in pieces
  /// from `equilibrium` when given and its tension asks for them, in more when they fail;
  /// free-free: the check that the loads balance). True when it converged; the trial state holds
  /// the equilibrium.
  bool SolveRestEquilibrium(const StepInput& input, const Vec6* base_wrench_B,
                            const RodState* equilibrium, StepSummary* summary);
  /// The unknowns at W (base wrench, N and N·m) and run_.state at `equilibrium`, twists zero.
  void StartFromEquilibrium(const RodState& equilibrium, const Vec6& W);
  /// After SolveRestEquilibrium: the trial state becomes the run's, with both history levels at
  /// it and every twist zero, at t = 0.
  void StartHistoryAtRest(const StepInput& input);
  /// With automatic pieces: as many as the tension of run_.state asks for at dt, if more.
  void AddPiecesForTension();
  /// With junctions_active_: restart the shot at junction k (node junction_nodes_[k]) from the
  /// state given by the junction unknowns, after recording the mismatch of the arriving state.
  /// Templated on the integration state, which is private to bdf2_shot.cpp.
  template <typename State>
  void ApplyJunction(int k, State* y);
  /// The state junction k restarts from: the last accepted state there displaced by its 18
  /// unknowns in junction_z_.
  template <typename State>
  State JunctionRestart(int k) const;
  /// junction_mismatch_ of junction k: arriving − restart, in the units of the unknowns.
  template <typename State>
  void RecordJunctionMismatch(int k, const State& arriving, const State& restart);
  /// Multiple shooting: shoots piece `piece` alone (from x at s = 0 for the first piece, from the
  /// restart of junction piece − 1 otherwise, with junction_z_). A piece before the last writes
  /// the mismatch of the junction it ends at to junction_mismatch_ and returns zero; the last
  /// piece returns the tip residual. The trial state of the piece's nodes is overwritten.
  Vec6 ShootPiece(const StepInput& input, const Coefficients& c, bool statics, int piece,
                  const Vec6& x);
  /// Multiple shooting: the block-banded Jacobian of the residual (junction mismatches, then the
  /// tip) in the unknowns [x; z] at ms_x_, piece by piece, factorised into ms_lu_. False when
  /// a shot is not finite or the Jacobian is singular.
  bool RenewJunctionJacobian(const StepInput& input, const Coefficients& c, bool statics,
                             StepSummary* summary);
  /// junction_nodes_ for the current grid (constructor, Grow()).
  void PlaceJunctions();
  /// Shoot in `pieces` pieces from now on: the junctions and the multiple-shooting workspace
  /// (constructor, and when automatic pieces grow).
  void SetShootingPieces(int pieces);
  int ShootingPieces() const { return static_cast<int>(junction_nodes_.size()) + 1; }
  /// After run_.drop_wait steps taken whole, pieces a failure added above ChosenPieces() are
  /// halved back towards it (a spike in the input must not leave every later step several times
  /// dearer for long). Allocates, as adding pieces does.
  void DropUnneededPieces();
  /// Pieces are about to be added after a failed attempt: a drop that had not held yet was too
  /// early, so the next one waits twice as long.
  void NoteAddedPieces();
  /// The most pieces the automatic choice goes to: kMostAutomaticPieces, and no more than the
  /// steps of the shot.
  int MaxAutomaticPieces() const;
  /// Whether automatic pieces can take the snapshot's number of pieces (Restore()).
  bool PiecesCanFollow(const Snapshot& snapshot) const;
  /// The automatic choice for a shot's exponent: one piece up to 10, else
  /// SuggestedShootingSegments, at most MaxAutomaticPieces().
  int PiecesFor(double exponent) const;
  void SetImplicitCompliance(double c0);
  /// The sample points of grid_ with their tendon offsets and sections (constructor, Grow()).
  void SampleGrid();
  /// Throws std::invalid_argument for an actuation this rod cannot take (Actuation::Require).
  void RequireActuation(const Actuation& a) const;
  /// The residual a solve from the unknowns x under `input` must reach: options().tolerance, or
  /// the round-off floor of a shot from x when that is larger (a rod carrying loads far above
  /// EI/L², or pressed on a stiff contact surface).
  double Tolerance(const Vec6& x, const StepInput& input) const;
  /// Throws std::invalid_argument when the base pose's R (or a held tip's) is not a rotation.
  void RequirePoses(const StepInput& input) const;
  /// Snapshot::model_fingerprint for the current grid (constructor, Grow()).
  std::uint64_t ModelFingerprint() const;
  /// Samples every section for actuation_ (SampleGrid() and when the actuation changes).
  void SampleSections();
  void ApplyActuation(const Actuation& actuation);
  /// Fills the history terms ξʰ, Vʰ at every stage for the weights c (once per step).
  void PrepareHistory(const Coefficients& c);
  /// The shot's steps: kRk4Pairs pairs equal segments (pair_start_), segments before `keep`
  /// keep their plan (Grow()); then each step's first stage slot (step_slot_). Needs samples_.
  void PlanSteps(int keep = 0);
  /// The fastest exponential rate (1/m) along s of the step's rod at a sample: bending or a wave.
  double StepRate(const Sample& smp) const;
  /// kRk4Pairs pairs two segments only where the pair's length times StepRate stays below this:
  /// RK4's error on e^{z} over one step is about z⁵/120, 2.6e-4 at z = ½.
  static constexpr double kMaxPairExponent = 0.5;
  /// Whether node i starts a step of the shot: a junction may sit only there.
  bool StepStartsAt(int i) const { return i == 0 || !pair_start_[i - 1]; }
  /// The scheme table and number of segments of the step that starts at node i.
  const internal::SchemeTable& StepTable(int i) const {
    return pair_start_[i] || options_.spatial_scheme != SpatialScheme::kRk4Pairs
               ? internal::Table(options_.spatial_scheme)
               : internal::kRk4Table;
  }
  int StepSpan(int i) const { return pair_start_[i] ? 2 : 1; }
  void Commit(double h);

  RodModel model_;
  Bdf2Options options_;
  std::vector<double> grid_;
  std::vector<double> sample_points_;  ///< s of every sample, m
  std::vector<Sample> samples_;        ///< 3 per segment: start, midpoint, end
  std::vector<TendonSample> tendons_;  ///< parallel to samples_; empty without tendons
  /// kRk4Pairs: pair_start_[i] when segments i and i + 1 are integrated as one RK4 step (equal
  /// lengths, no section breakpoint on node i + 1); all false for the other schemes.
  std::vector<char> pair_start_;
  /// The first stage slot (index into the stage arrays) of the step that starts at node i.
  std::vector<int> step_slot_;
  int stage_slots_ = 0;  ///< stage slots of the whole shot
  Actuation actuation_;  ///< the actuation the samples are for
  Vec6 scale_;           ///< W(0) = scale ⊙ x

  Snapshot run_;  ///< the accepted run: all Save() and Restore() copy

  // The shot being tried, at the same stage points (swapped into run_ on acceptance).
  std::vector<Vec6> strain_now_, twist_now_;
  std::vector<Vec3> position_now_, velocity_W_now_;
  std::vector<Mat3> rotation_now_;
  Vec6 tip_strain_now_ = Vec6::Zero(), tip_twist_now_ = Vec6::Zero();
  lie::SE3 base_now_;
  RodState trial_;
  /// strain_now_ holds the stage strains of a dynamic shot of the current step (a first guess
  /// for the tendon strain law); false after Commit, Restore, Grow and statics.
  bool stage_strains_current_ = false;

  // Per-step caches.
  std::vector<Vec6> strain_h_, twist_h_;  ///< history terms ξʰ, Vʰ for history_c_
  std::vector<Vec3> velocity_W_h_;
  Coefficients history_c_;
  bool history_ready_ = false;
  Vec6 xi_back_ = Vec6::Zero();  ///< log(g₁⁻¹ g₂) at s = 0, for the group BDF2 of free-free
  double current_c0_ = -1.0;
  Vec6 solved_unknowns_ = Vec6::Zero();
  /// What Commit() appends to the predictor's history: the solved unknowns plus the Newton
  /// correction of their remaining residual (no shot), so the history carries less of the
  /// solver's own error; the predictor's high degrees amplify that error by up to 2047.
  Vec6 predictor_term_ = Vec6::Zero();

  Vec6 twist_scale_;  ///< V(0) = twist_scale ⊙ x for free-free: [1/s ×3, L/s ×3]

  // Multiple shooting (shooting_segments > 1). Junction k restarts at node junction_nodes_[k]
  // from the last accepted state there, displaced by 18 unknowns z: [δp/L, δθ (rad, body),
  // δm/(EI/L), δn_W/(EI/L²), δω·(1 s), δv·(1 s)/L].
  std::vector<int> junction_nodes_;
  bool junctions_active_ = false;
  Eigen::VectorXd junction_z_;         ///< the unknowns of the shot being tried
  Eigen::VectorXd junction_mismatch_;  ///< arriving − restart state, same units, per junction
  Eigen::VectorXd ms_x_, ms_x_new_, ms_r_, ms_r_new_, ms_dx_;
  Eigen::VectorXd ms_piece_base_, ms_piece_new_;  ///< one piece's end residual, for the Jacobian
  bool initialized_ = false;
  bool automatic_pieces_ = false;  ///< Bdf2Options::shooting_segments was 0
  int initial_pieces_ = 1;  ///< the constructor's plan, which every InitializeAtRest starts from
};

}  // namespace cosserat
