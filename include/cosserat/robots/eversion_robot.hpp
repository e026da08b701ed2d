#pragma once
/// \file
/// Eversion ("vine") robots and inflated beams (Suulker et al. 2026; docs/eversion.md): a
/// thin-walled tube inflated to a gauge pressure p, clamped at its base (s = 0), that grows by
/// everting new wall material at its tip (s = L). Built on InflatedTubeSection (stiffness E_eff(p)
/// I, constrictive bands) and StaticShootingSolver (cantilever statics).
///
/// Pressure load. The pressure on the tip pushes the tip outward, along the body tangent d3(L):
/// a follower tip force of magnitude p A_tip, A_tip = π r(L)², carried by the wall as tension.
/// Sign convention: positive p pushes the tip away from the base (tension in the wall, axial
/// strain Γ3 − 1 = p A / EA > 0). Two models of how the rest of the pressure acts:
///   - kClosedVessel (default): the pressure on the tip cap *and* on the curved side wall. The
///     pressure on a closed tube is self-equilibrated, so it stretches the wall (wall tension
///     p A(s) along d3 everywhere) but neither bends the tube nor stiffens it in bending (Comer &
///     Levy 1963, Fichter 1966). Implemented exactly as a rest-strain shift: the solver's wrench
///     W is the net wrench of wall + air, with Γ3* = 1 + (1 − 2ν) p A(s)/EA(s) (the hoop stress
///     p r/t shortens the wall by ν p r/(E t)); the wall's own wrench is
///     W + [0; 0; 0; 0; 0; p A(s)] (body frame), i.e. the tip follower force p A_tip on the wall.
///   - kTipFollowerOnly: the follower tip force p A_tip alone (a body-frame tip force on the rod),
///     without the pressure on the curved side wall. This is the literal "follower tip force"
///     model; on a bent body it adds a moment that amplifies the bending, which the real tube
///     does not have (docs/eversion.md).
///
/// Growth. Material keeps its arc length s from the base: growing from L to L' adds the
/// material (L, L'] at the tip and leaves [0, L] where it is (the base is fixed). Each growth
/// step is a static solve of the body of the new length, warm-started from the previous length.
/// Bands are given in these material coordinates, over the whole stored tube [0, max_length];
/// only the everted part [0, L] of them is in the body.
///
/// Kink check. After every solve the bending moment |m_⊥(s)| = |(m1, m2)| at each grid node is
/// compared with the wrinkling moment M_w(s) = N(s) r(s) / 2, N the wall's axial force
/// (WallTension; under inflation alone N = p π r², M_w = π p r³ / 2, Comer & Levy 1963; a push
/// lowers it); a kink is
/// reported (KinkReport), never silently ignored. The rod model beyond the wrinkling moment is
/// not valid (the real tube loses stiffness there): a kinked solve is an honest report that the
/// design fails, not a prediction of the kinked shape.
///
/// Units SI; pressures gauge, Pa. Errors in the design or arguments throw std::invalid_argument
/// whose message starts with the name of the offending field.

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

/// How the inflation pressure loads the rod (see the file comment).
enum class PressureLoadModel {
  kClosedVessel,     ///< tip and side-wall pressure: wall tension p A(s), no bending effect
  kTipFollowerOnly,  ///< follower tip force p A_tip only (amplifies bending; for comparison)
};

/// A constrictive band: an inextensible ring that narrows the tube over [start, end) of material
/// arc length (m from the base) to diameter_ratio times the nominal diameter and multiplies the
/// bending and torsion stiffness by factor α (α ≈ 0.36 for a band that halves the diameter,
/// Suulker et al. 2026). Its wrinkling moment is diameter_ratio³ times the nominal one.
using EversionBand = InflatedTubeSection::Constriction;

/// The constant description of an eversion robot.
struct EversionRobotDesign {
  double radius = 0.0;          ///< nominal tube radius r, m (> 0)
  double wall_thickness = 0.0;  ///< wall thickness t, m (0 < t < r)
  ModulusLaw wall_modulus;      ///< E_eff(p), Pa, non-decreasing in p, > 0
  double poisson_ratio = 0.45;  ///< of the wall (LDPE ≈ 0.45), in (−1, 0.5]
  double wall_density = 920.0;  ///< kg/m³ (LDPE ≈ 920); the air inside is taken as buoyancy-neutral
  KelvinVoigtDamping damping;       ///< for dynamics; unused in statics
  std::vector<EversionBand> bands;  ///< material coordinates, within [0, max_length], no overlap
  /// Layer-jamming segments (Do et al. 2023): EI = EI_tube + E_ℓ(ΔP_k) I_ℓ in segment k,
  /// ΔP_k set by EversionRobot::SetJammingPressure (0: compliant). Material coordinates, sorted by
  /// start, within [0, max_length], no overlap, at most Actuation::kMaxSegments; not combined
  /// with a band on the same stretch of tube. The wrinkling (kink) moment stays the tube's: the
  /// stack's own resistance to wrinkling is not modelled (conservative).
  std::vector<JammingSegment> jamming;
  double max_length = 0.0;          ///< stored tube: the body can evert up to this length, m
  lie::SE3 base;                    ///< pose of the base clamp (s = 0) in the world
  PressureLoadModel pressure_load = PressureLoadModel::kClosedVessel;

  /// Throws std::invalid_argument naming the field ("radius: must be > 0", "bands[1]: ...").
  void Validate() const;
};

/// The design of a robot made of `tube` (radius, wall, modulus law, ν, density, damping and its
/// constrictions as bands), able to evert up to max_length from `base`: what a problem file's
/// "inflated" stiffness profile describes.
EversionRobotDesign DesignFromTube(const InflatedTubeSection& tube, double max_length,
                                   const lie::SE3& base);

struct EversionOptions {
  /// Grid density of the body: max(min_nodes, ceil(L · nodes_per_metre) + 1) nodes, plus two
  /// per everted band (its ends are nodes).
  double nodes_per_metre = 40.0;
  int min_nodes = 11;
  /// The most grid nodes the body may need at its full length (max_length · nodes_per_metre):
  /// a longer robot is refused at construction, before any grid is built.
  static constexpr double kMaxNodes = 1e6;
  /// The longest body these options grid within kMaxNodes, m.
  double MaxLength() const { return kMaxNodes / nodes_per_metre; }
  StaticShootingOptions solver;
  /// A single shot's exponent (StaticShootingExponent: a floor's β L, sqrt(T/EI) L) above which
  /// the body is solved in multiple-shooting pieces first, as a plain rod's statics are.
  double pieces_above_exponent = 10.0;
  /// The same where the last solve pressed on a contact surface (PressesOn; not a surface the
  /// body does not touch, which leaves it its stability index). The penalty's Jacobian jumps as
  /// nodes touch down, and a single shot warm-started from the last base wrench stalls well
  /// below 10: a 25 mm tube on a floor took ~40 Newton iterations a growth step at βL = 8,
  /// ~1 000 at βL = 9.4, against 2 or 3 for the multiple-shooting solver started from the last
  /// shape (one piece up to 10).
  double pieces_on_contact_above_exponent = 6.0;
};

/// Where and how badly the body exceeds its wrinkling moment.
enum class KinkStatus {
  kNone,       ///< |m_⊥| < M_w at every node
  kWrinkled,   ///< M_w <= |m_⊥| < M_c = 2 M_w somewhere: the wall wrinkles, the tube kinks
  kCollapsed,  ///< |m_⊥| >= M_c somewhere: the wrinkle spans the section (Comer & Levy collapse)
};
/// "none", "wrinkled", "collapsed".
const char* ToString(KinkStatus status);

struct KinkReport {
  KinkStatus status = KinkStatus::kNone;
  /// max over nodes of the factor by which the bending moment and the torque there pass the
  /// membrane's wrinkling onset: |m_⊥(s)| / M_w(s) without torque; inf where the wall has no
  /// axial tension left (pushed slack, or uninflated and not pulled), or p = 0 under a torque
  double max_ratio = 0.0;
  double s_max = 0.0;      ///< where the ratio is largest, m
  double moment = 0.0;     ///< |m_⊥| there, N·m
  double torque = 0.0;     ///< |m₃| there, N·m
  double wrinkling_moment = 0.0;  ///< M_w = N r/2 there, N·m (the governing side at a band end)
  double first_kink_s = -1.0;     ///< smallest s with ratio >= 1, m; −1 if none
  bool kinked() const { return status != KinkStatus::kNone; }
};

struct EversionSolveSummary {
  double length = 0.0;  ///< everted length L of this solve, m
  StaticShootingSummary solve;
  KinkReport kink;  ///< meaningful when the solve converged
  /// Converged and not kinked.
  bool ok() const { return solve.converged() && !kink.kinked(); }
};

struct GrowthSummary {
  int steps = 0;                              ///< growth steps solved (converged ones)
  double length = 0.0;                        ///< length reached, m
  SolveStatus status = SolveStatus::kNotRun;  ///< kConverged if every step converged
  int first_kink_step = -1;  ///< first step (1-based) whose solve reported a kink; −1: none
  double first_kink_length = -1.0;
  KinkReport worst_kink;  ///< the largest ratio met
  /// The last step's solve (its status, residual and stability index), counting the work of
  /// every step (iterations, shots, load steps, wall time).
  StaticShootingSummary last_solve;
  bool converged() const { return status == SolveStatus::kConverged; }
};

class EversionRobot {
 public:
  /// The body everted to `initial_length` (0 < L0 <= max_length) at `pressure` (>= 0). Throws
  /// std::invalid_argument naming the field on bad input. No solve is run yet.
  EversionRobot(EversionRobotDesign design, double initial_length, double pressure,
                EversionOptions options = {});

  /// A new inflation pressure (Pa, >= 0, else invalid_argument "pressure: ..."). Rebuilds the
  /// solver (allocates); the next Solve warm-starts from the last solution.
  void SetPressure(double pressure);
  /// The tension of the tail (N, >= 0; default 0): the inner material pulled back through the
  /// body to a reel at the base. The tip's balance is p A = N_wall + T_tail + F, so the tail
  /// takes T_tail off the wall's tension (its stretch and wrinkling moment) without bending the
  /// body (it runs along the axis, as a tendon at zero offset does). Growth against a braked reel
  /// has T_tail = (p A − F)/2. kClosedVessel only: invalid_argument "tail_tension: ..." for a
  /// negative or non-finite T_tail, or a positive one with kTipFollowerOnly.
  void SetTailTension(double tension);
  /// Statics of the body everted to `length` (0 < L <= max_length, else invalid_argument
  /// "length: ...") under `loads` (gravity, distributed force, external tip wrench). The
  /// pressure load is added by the robot (kTipFollowerOnly needs any external tip force in the
  /// body frame, or zero). Warm-starts from the previous solve; falls back to a cold solve if
  /// that fails. Then checks the kink.
  EversionSolveSummary Solve(double length, const StaticLoads& loads);
  /// Solve at the current length.
  EversionSolveSummary Solve(const StaticLoads& loads) { return Solve(length_, loads); }
  /// Quasi-static growth from the current length to `target_length` in `steps` equal length
  /// increments, one warm-started solve each. Stops at the first step that does not converge.
  /// Kinks are recorded and growth goes on. on_step(k, summary, robot) runs after step k
  /// (1-based) with the robot holding that equilibrium.
  using StepCallback =
      std::function<void(int step, const EversionSolveSummary& summary, const EversionRobot&)>;
  GrowthSummary Grow(double target_length, int steps, const StaticLoads& loads,
                     const StepCallback& on_step = {});

  /// The kink check of the current state (see the file comment).
  KinkReport CheckKink() const;

  // --- The model at the current pressure ---------------------------------------------------
  /// The rod model of the body everted to `length` at the current pressure: the section profile
  /// (bands clipped to [0, L]) and, for kClosedVessel, the pressure rest strain. Solve it with a
  /// StaticShootingSolver built with actuation() and the loads of SolverLoads().
  RodModel ModelAt(double length) const;
  /// Number of grid nodes used for a body of `length`.
  int NodesAt(double length) const;
  /// The loads the solver sees for these external loads on the body everted to `length`: for
  /// kTipFollowerOnly the follower tip force p π r(L)² e3 (body frame) is added; kClosedVessel
  /// adds nothing (the pressure is in the rest strain). Throws "loads.tip_force: ..." for a
  /// world-frame external tip force with kTipFollowerOnly.
  StaticLoads SolverLoads(const StaticLoads& external, double length) const;
  /// Actuation with the current pressure and jamming pressures (what the profile reads).
  Actuation actuation() const;
  /// Jamming pressure difference ΔP (Pa, >= 0) of design().jamming[k]. Throws invalid_argument
  /// "jamming_pressure[k]: ..." for a k outside the list or a negative or non-finite ΔP. The
  /// next Solve rebuilds the solver and warm-starts from the last solution.
  void SetJammingPressure(int k, double pressure);
  /// The profile of the whole stored tube [0, max_length] (all bands), at any pressure.
  const InflatedTubeSection& full_profile() const { return *full_profile_; }

  double RadiusAt(double s) const { return full_profile_->RadiusAt(s); }  ///< m
  /// E_eff(p) I α at s, plus E_ℓ(ΔP) I_ℓ in a jamming segment, N·m².
  double BendingStiffnessAt(double s) const;
  /// Axial stiffness E_eff(p) · 2π r t, N.
  double AxialStiffness() const;
  /// The inflated tube's M_w(s) = π p r(s)³ / 2, N·m, without axial loads (CheckKink uses the
  /// wall's axial force of the solved state).
  double WrinklingMomentAt(double s) const;
  /// The follower tip force p π r(L)² at the current length, N, pushing outward along d3(L).
  double TipForce() const;
  /// Axial strain of the straight, unloaded body in free space (away from bands): in the closed
  /// vessel the thin isotropic wall's (σ_x − ν σ_θ)/E = (1 − 2ν) p r / (2 E_eff t), less
  /// T_tail / EA; under the tip follower force alone p π r² / (E_eff 2π r t) = p r / (2 E_eff t).
  double FreeAxialStrain() const;

  // --- State ---------------------------------------------------------------------------------
  double length() const { return length_; }
  double pressure() const { return pressure_; }
  double tail_tension() const { return tail_tension_; }  ///< N
  const EversionRobotDesign& design() const { return design_; }
  const EversionOptions& options() const { return options_; }
  /// The last solve's state (net wrench of wall, air and tail in wrench_B; see the file
  /// comment). Throws std::logic_error before the first Solve.
  const RodState& state() const;
  /// Axial force in the wall at node i of the state, N: W3 + p A(s) − T_tail for kClosedVessel,
  /// W3 for kTipFollowerOnly (where W already is the wall's).
  double WallTension(int node) const;
  /// The single-shot solver of the current length and pressure (null before the first Solve).
  const StaticShootingSolver* solver() const { return solver_.get(); }
  /// Multiple-shooting pieces of the last converged solve: 1 for one shot; more where one shot
  /// failed and the body was solved in pieces (a long robot on a stiff floor).
  int pieces() const { return in_pieces_ ? pieces_->pieces() : 1; }

 private:
  /// WallTension at node i with the section radius r there (m): a band's end has two.
  double WallTensionAt(int node, double r) const;
  void RebuildSolver(double length);
  /// After a failed single shot, or first when the last solve was in pieces: the body by
  /// multiple shooting; on success *summary is its (counting the failed work too) and the state
  /// is pieces_'s. With from_last, Newton starts from the last solution in pieces, carried onto
  /// this length's grid, before following the loads from the unloaded body.
  void SolveInPieces(double length, const StaticLoads& solver_loads, bool from_last,
                     StaticShootingSummary* summary);
  /// First-order guess of W(0) (base body frame) at a new length from the current solution.
  Vec6 PredictBaseWrench(double length, const StaticLoads& solver_loads) const;
  EversionRobotDesign design_;
  EversionOptions options_;
  std::shared_ptr<const InflatedTubeSection> full_profile_;
  double length_ = 0.0;
  double pressure_ = 0.0;
  double tail_tension_ = 0.0;  ///< N
  std::array<double, Actuation::kMaxSegments> jamming_pressure_{};  ///< ΔP of each segment, Pa
  std::unique_ptr<StaticShootingSolver> solver_;
  std::unique_ptr<StaticMultipleShootingSolver> pieces_;  ///< where one shot failed
  bool in_pieces_ = false;  ///< the state is pieces_'s (the next solve tries pieces first)
  double solver_length_ = -1.0;
  bool solver_stale_ = true;
  double solved_pressure_ = 0.0;      ///< the pressure of the state
  double solved_tail_tension_ = 0.0;  ///< the tail tension of the state, N
  bool have_solution_ = false;    ///< last_base_wrench_ is a converged W(0)
  Vec6 last_base_wrench_ = Vec6::Zero();
};

}  // namespace cosserat
