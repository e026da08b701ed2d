#pragma once
/// \file
/// Natural frequencies and mode shapes of a rod linearised about a static equilibrium (the
/// straight rest state, or a rod sagging under gravity, bent by tip loads, or stiffened by an
/// actuated section profile). Two independent formulations (docs/modes.md):
///
/// - Quaternion FD (ComputeModes): solve the statics of the Lang & Linn model, linearise
///   v̇ = f(q, v) there with the analytic banded Jacobian, restrict to the tangent space of the
///   constraints (free vertices δx_n; per segment a body rotation θ_ν with δp = ½ p ⊗ [0; θ]), and
///   solve  K φ = ω² M φ  (symmetric when the loads are conservative) or, for follower loads,
///   the non-symmetric eigenproblem of M⁻¹K; with Kelvin–Voigt damping also the quadratic
///   eigenproblem λ² M + λ C + K = 0 (damped frequencies and damping ratios).
/// - SE(3) shooting (ComputeModesShooting, frequency_shooting.hpp): the strong form linearised
///   about the equilibrium in the frequency domain; the 6×6 tip-boundary matrix B(ω) of the
///   cantilever or the column is singular exactly at a natural frequency.

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "cosserat/analysis/column_ends.hpp"
#include "cosserat/lie/se3.hpp"
#include "cosserat/lie/types.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/state/solve_status.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

/// Which motion carries most of a mode's kinetic energy (translation along / across the local
/// tangent, rotation about / across it).
enum class ModeKind {
  kBending,  ///< transverse translation + rotation about a section axis
  kTorsion,  ///< rotation about the tangent
  kAxial,    ///< translation along the tangent
};
const char* ToString(ModeKind kind);

/// One undamped mode.
struct Mode {
  double omega = 0;         ///< natural circular frequency ω, rad/s
  double frequency_hz = 0;  ///< ω / 2π, Hz
  ModeKind kind = ModeKind::kBending;
  /// quatfd: a neutral mode, a motion that costs no energy (a bowed line turning about the
  /// chord that gravity runs along, or an equilibrium at its critical load). Its computed ω² is
  /// round-off: below ε times the largest |(M⁻¹K)_ii| and 1e4 below the next mode's. Listed at
  /// ω = 0, and neither the stability nor the grid is judged by it.
  bool neutral = false;
  double computed_omega_squared = 0;  ///< a neutral mode's ω² as computed (round-off), rad²/s²
  /// Shares of the kinetic energy (sum 1): translation across / along the tangent, rotation
  /// about the tangent, rotation across it.
  double share_transverse = 0, share_axial = 0, share_twist = 0, share_tilt = 0;
  /// Shape at the grid nodes: displacement (world, m) and small rotation vector (world, rad) per
  /// unit amplitude, scaled so that max_n max(|δx_n| / L, |δθ_n|) = 1 and the entry of largest
  /// magnitude is positive. Empty when shapes were not asked for.
  std::vector<Vec3> displacement_W;
  std::vector<Vec3> rotation_W;
};

/// One damped mode: λ = −ζ ω_n ± i ω_d (underdamped pairs only).
struct DampedMode {
  double omega_n = 0;              ///< |λ|, rad/s
  double damped_frequency_hz = 0;  ///< ω_d / 2π, Hz
  double damping_ratio = 0;        ///< ζ = −Re λ / |λ|
};

enum class ModalStatus {
  kNotRun,
  kConverged,      ///< the equilibrium converged and `count` modes were found
  kStaticsFailed,  ///< the static equilibrium did not converge (no modes computed)
  kUnstable,       ///< the equilibrium has an eigenvalue ω² < 0 or a complex one (flutter) below
                   ///< the modes returned: it is not a stable equilibrium
  kTooFewModes,    ///< fewer than `count` modes exist (quatfd) or were found in the scanned band
                   ///< (shooting); the ones found are returned
};
const char* ToString(ModalStatus status);

struct ModalOptions {
  int count = 4;       ///< how many of the lowest modes to return (with multiplicity)
  bool shapes = true;  ///< compute mode shapes
  bool damped = true;  ///< quatfd: also the damped modes when the model has damping
  /// quatfd: above this many reduced coordinates (six per segment; 300 is about 51 nodes), a
  /// symmetric, positive definite stiffness without damping to resolve has its lowest modes
  /// found by subspace iteration on its banded factorisation, in time linear in the nodes (a
  /// stay cable on 401 nodes: 24 s dense); the dense spectrum otherwise, and where that fails.
  int sparse_above = 300;
  /// quatfd: the largest dense spectrum taken, in reduced coordinates, twice them for damped
  /// modes (its cost grows as their cube: 4800, about 801 nodes undamped or 401 damped, take
  /// ~5 min and 1.6 GB); beyond, where the banded path declines, no modes are computed and
  /// ModalResult::declined says why.
  int max_dense = std::numeric_limits<int>::max();
  bool IsValid(std::string* why) const;
};

struct ModalResult {
  ModalStatus status = ModalStatus::kNotRun;
  SolveStatus statics_status = SolveStatus::kNotRun;
  int statics_iterations = 0;     ///< Newton iterations of the equilibrium solve
  double statics_residual = 0.0;  ///< its final residual (the solver's norm)
  std::vector<double> s;    ///< node arc lengths of the shapes, m
  RodState equilibrium;     ///< the static equilibrium linearised about (last iterate if failed)
  std::vector<Mode> modes;  ///< the lowest `count`, by frequency
  /// With ModalStatus::kUnstable: why (divergence, with ω² or the Morse index; or flutter).
  std::string instability;
  /// With ModalStatus::kNotRun after a converged equilibrium: why no modes were computed (a
  /// spectrum the banded path declined, larger than ModalOptions::max_dense).
  std::string declined;
  /// With `declined`: the dense eigenproblem's size it would have taken.
  int declined_dense_size = 0;
  /// quatfd only: the damped pair of each of `modes`, in their order (NaN frequency and ratio
  /// for a mode without one: overdamped, or unstable).
  std::vector<DampedMode> damped;
  /// quatfd: whether the stiffness was symmetric (conservative loads) and the symmetric solver
  /// was used. Shooting: always false.
  bool symmetric = false;
  /// quatfd: whether the modes came from the banded factorisation (ModalOptions::sparse_above)
  /// rather than the dense spectrum.
  bool sparse = false;
  /// SE(3) shooting: the frequency past which one shot's round-off blurs the roots and none is
  /// listed (Hz; 0 on quaternion FD, and where the rod's tension alone passes that limit).
  double shot_limit_hz = 0;
  double wall_time_s = 0;
  bool converged() const { return status == ModalStatus::kConverged; }
  std::vector<double> frequencies_hz() const;
};

/// Quaternion-FD modes about the equilibrium of `model` under `loads`: the statics are solved
/// from q_guess (the rest state if null), then the linearisation is reduced to the 3 (free
/// vertices) + 3 (segments) physical directions per node: the quaternion-norm directions and
/// the prescribed base vertex carry only the zero eigenvalues of the constraints and are left
/// out. If `q_equilibrium` is set it receives the equilibrium. Costs one dense eigenproblem of
/// size 6N + 3 (12N + 6 with damping): about 0.1 s at N = 100 without damping.
ModalResult ComputeModes(quatfd::QuatFdModel* model, const StaticLoads& loads,
                         const ModalOptions& options = {}, const Eigen::VectorXd* q_guess = nullptr,
                         Eigen::VectorXd* q_equilibrium = nullptr,
                         const quatfd::QuatFdStaticsOptions& statics = {});

/// Options of the frequency scan of the shooting formulation.
struct ShootingModalOptions {
  ModalOptions modal;
  /// Scan band (rad/s). omega_min = 0 means 0.01 × the Euler–Bernoulli first cantilever
  /// frequency of the section at s = 0; omega_max = 0 means 1e4 × that frequency.
  double omega_min = 0, omega_max = 0;
  /// Geometric step of the coarse scan of σ_min(B(ω)); roots closer than this are separated by
  /// the recursive refinement down to 1e-10 ω (closer ones count as one multiple root).
  double relative_step = 0.005;
  StaticShootingOptions statics;
  /// A rigid body at the cantilever's tip (ShootingEnds::tip_mass, tip_inertia: kg; kg·m² about
  /// the tip's body axes): its inertia joins the tip condition; its weight must be in the loads
  /// (a dead tip force). Not for a column.
  double tip_mass = 0.0;
  Vec3 tip_inertia = Vec3::Zero();
  /// Called during the scan with the modes found so far and `modal.count` (a progress line; it
  /// may throw to stop the run, as Ctrl-C from Python does). Empty: not called.
  std::function<void(double found, double asked)> progress;
  bool IsValid(std::string* why) const;
};

/// SE(3)-shooting modes of the cantilever (`rod` clamped at `base`) about its equilibrium under
/// `loads`, on `num_nodes` grid points with RK4 in s; or, with other `ends`, of the column
/// (ColumnSolver's equilibrium followed from the unloaded column; its tip guided along base.R's
/// third column, which carries the tip's axial load). Undamped only (the section damping is
/// ignored); no tendons (throws std::invalid_argument). Section actuation (pressure, jamming) is
/// applied through the profile.
ModalResult ComputeModesShooting(const RodModel& rod, int num_nodes, const lie::SE3& base,
                                 const StaticLoads& loads, const ShootingModalOptions& options = {},
                                 const Actuation& actuation = {},
                                 ColumnEnds ends = ColumnEnds::kClampedFree);

}  // namespace cosserat
