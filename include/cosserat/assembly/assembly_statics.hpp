#pragma once
/// \file
/// Statics of an Assembly (assembly.hpp) by shooting all its rods together. The unknowns: each
/// rod's base wrench (its moment about its own tangent replaced by its spin angle for a
/// torsion-free base) and each body's pose; in the inverse problem each rod's length instead of
/// the bodies' poses. The residuals: each rod's tip condition (free: no wrench; joined: the joint's
/// position and rotation conditions, and no moment where it turns freely) and each body's force
/// and moment balance, with the rods' tip wrenches acting on it. One Newton system for the
/// whole structure (the junction conditions of the applications chapter of the source, eq. 10.1,
/// without inertia). Levenberg–Marquardt on it, with the exact Jacobian of each rod's shot along
/// its unknowns (a tangent shot, rod_shot.hpp; its length by a forward difference) and of the
/// joints' algebra (ceres::Jet); a warm re-solve first takes quasi-Newton steps with the last
/// inverse Jacobian, updated by Broyden's formula. When a solve from the last solution fails it follows
/// the loads and the lengths (or the poses) from that solution, halving its steps.

#include <chrono>
#include <vector>

#include <Eigen/Dense>

#include "cosserat/assembly/assembly.hpp"
#include "cosserat/assembly/rod_shot.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/state/solve_status.hpp"

namespace cosserat {

struct AssemblyOptions {
  /// Convergence: the residual's 2-norm, dimensionless (positions over the rod's length,
  /// rotations in rad, moments over EI/L, forces over EI/L², the body's over its rods' largest).
  double tolerance = 1e-10;
  int max_iterations = 50;  ///< Levenberg–Marquardt iterations per continuation level
  int max_load_steps = 64;  ///< continuation levels (accepted and rejected) per solve
};

struct AssemblySummary {
  SolveStatus status = SolveStatus::kNotRun;
  int iterations = 0;
  int jacobians = 0;   ///< exact Jacobians evaluated (the other iterations reuse the last one)
  int load_steps = 0;  ///< continuation levels beyond the direct solve
  double residual = 0.0;  ///< at the last load level reached (load_fraction of the loads)
  double wall_time_s = 0.0;
  /// The fraction of the way from the start to the loads (and lengths or poses) that the
  /// continuation reached: 1 when converged; the state is that level's.
  double load_fraction = 1.0;
  bool converged() const { return status == SolveStatus::kConverged; }
};

class AssemblyStaticsSolver {
 public:
  /// Throws std::invalid_argument when the assembly is not valid (Assembly::IsValid).
  explicit AssemblyStaticsSolver(const Assembly& assembly, const AssemblyOptions& options = {});

  /// Forward problem: the bodies' poses and the rods' shapes for the rods' `lengths` (m, one per
  /// rod; empty: each model's length) under `loads` (their gravity also weighs the bodies; tip
  /// loads are not used: load a body instead). Starts from the last solution; when it fails, the
  /// solver keeps that solution as the next solve's start (the state then reports it).
  AssemblySummary Solve(const StaticLoads& loads, const std::vector<double>& lengths = {});

  /// Inverse problem: the rods' lengths that hold each body at `poses` (one per body) under
  /// `loads`. Needs six rods per body (throws std::invalid_argument otherwise).
  AssemblySummary SolveLengths(const StaticLoads& loads, const std::vector<lie::SE3>& poses);

  /// d(pose of `body`)/d(lengths) at the last converged forward solution (6 × rods): rows
  /// dp_W (m/m) and dθ (rad/m) with R(L + dL) ≈ R Exp(dθ dL), the body frame. From the
  /// solution's Jacobian by the implicit function theorem. Empty without a solution.
  Eigen::MatrixXd PoseJacobian(int body, const StaticLoads& loads);

  /// The bodies' condensed stiffness at the last converged forward solution: the change of
  /// their balance residuals per change of their poses with every rod kept in equilibrium (the
  /// Schur complement of the rods' block of the solve's Jacobian), scaled as the solve's
  /// unknowns and residuals (6 bodies × 6 bodies). Empty without a solution.
  Eigen::MatrixXd CondensedBodyStiffness(const StaticLoads& loads);
  /// The unstable directions of the bodies at the last converged forward solution: the
  /// eigenvalues of CondensedBodyStiffness with a positive real part (above 1e-8 of the
  /// largest), a restoring stiffness being negative in the balance residual. It counts what the
  /// bodies' motion can release with every rod in equilibrium; a rod unstable with its ends
  /// held (past a conjugate point) adds directions it does not see (Haynsworth 1968). −1 when not
  /// defined: no solution, no bodies, or a body carrying an applied moment (a dead moment is not
  /// conservative in 3-D).
  int BodyStabilityIndex(const StaticLoads& loads);

  const std::vector<lie::SE3>& body_poses() const { return poses_; }
  const std::vector<double>& lengths() const { return lengths_; }
  /// The node states of rod i at the last solve (s from 0 to its length), recorded on the first
  /// call after a solve.
  const RodState& rod_state(int i);
  int rod_count() const { return static_cast<int>(rods_.size()); }

 private:
  enum class Mode { kForward, kInverse };
  /// The convergence threshold under `loads`: options.tolerance, or the round-off floor of the
  /// balance when that is larger (forces far above the most compliant rod's EI/L², e.g. a plate
  /// on taut wires: 625 times it leaves a balance of ~5e-10 that no step can reduce). With
  /// `stall_floor`, also the residual below which a solve that stops progressing has converged
  /// as far as its stiffest rods' axial resolution allows (~10 ε ΣEA).
  double Tolerance(const StaticLoads& loads, double* stall_floor = nullptr) const;
  template <typename T>
  using Point = RodShot::Point<T>;
  /// Per rod: its shot, scales (moment EI/L, force EI/L²), and the last shot's tip.
  struct Rod {
    RodShot shot;
    double moment_scale = 1.0, force_scale = 1.0;
    Point<double> tip;
  };
  /// Rod i's state at s = 0 for its 6 base unknowns x, its base on a body at (p_body, R_body)
  /// (the world: zero and identity); the second form at the current unknowns.
  template <typename T>
  Point<T> BaseStart(int i, const Vector6<T>& x, const Vector3<T>& p_body,
                     const Matrix3<T>& R_body) const;
  Point<double> BaseStart(int i) const;
  /// The tangent of rod i's start along its base body's pose increment [δp; δθ].
  rhs::StaticTangent BodyStartTangent(int i, const Point<double>& start) const;
  template <typename T>
  Vector6<T> TipResidual(int i, const Point<T>& tip, const Vector3<T>& p_b,
                         const Matrix3<T>& R_b) const;
  /// The force and moment about the body's origin (p_b) that a rod end exerts on the body it is
  /// joined to (world): the base with sign +1, the tip with −1.
  template <typename T>
  void EndWrenchOnBody(const Point<T>& end, double sign, const Vector3<T>& p_b, Vector3<T>* f,
                       Vector3<T>* m) const;

  /// The tangent of rod i's start along its 6 base unknowns, at the start `start`.
  rhs::StaticTangent StartTangent(int i, const Point<double>& start) const;
  int Unknowns() const;
  /// Shoots every rod at the current unknowns; false if a shot is not finite.
  bool ShootAll();
  void Residual(const StaticLoads& loads, Eigen::VectorXd* r) const;
  /// d residual / d unknowns; with J_length, also d residual / d lengths (rows × rods).
  void Jacobian(const StaticLoads& loads, Eigen::MatrixXd* J, Eigen::MatrixXd* J_length);
  /// Jacobian's columns of rod i's unknowns (its length into J_length or, in the inverse
  /// problem, J; its base body's pose in the forward one) in every row they reach.
  void AddRodColumns(int i, Eigen::MatrixXd* J, Eigen::MatrixXd* J_length);
  /// Jacobian's columns of body b's pose in the rows of the rods' tips on it and its balance.
  void AddBodyColumns(int b, Eigen::MatrixXd* J);
  /// Follows at(μ), μ: 0 → 1, from a solution at μ = 0 (the current unknowns), halving a step
  /// that fails and doubling one that succeeds; at(μ) sets the lengths or poses of level μ and
  /// returns its loads. Returns the last μ reached.
  template <typename At>
  double Follow(const At& at, AssemblySummary* summary);
  void Apply(const Eigen::VectorXd& dz, double scale);
  bool LevenbergMarquardt(const StaticLoads& loads, AssemblySummary* summary);
  /// Whether some body has an applied force or moment (besides its weight).
  bool HasBodyForces() const;
  /// A point of the solve (its unknowns), to go back to.
  struct Iterate {
    Eigen::VectorXd x;
    std::vector<lie::SE3> poses;
    std::vector<double> lengths;
  };
  void Store(Iterate* u) const;
  void Load(const Iterate& u);
  /// Forward solves: whether a body's pose moved from `from` further than one solve of a load
  /// step should take it (a jump to another branch).
  bool JumpedFrom(const Iterate& from) const;
  /// Ends a solve: a solution becomes the next start; a failure goes back to `start` when there
  /// was a solution before; the summary's status and time.
  void Conclude(bool converged, const StaticLoads& loads, const Iterate& start,
                std::chrono::steady_clock::time_point t0, AssemblySummary* summary);
  /// Applies dz_ and, with `chord_steps` (dz_ a full Newton step, factors lu_), while the
  /// residual (into r_trial_) is not below `norm`, a few chord steps after it; true, with the
  /// state there, once one is below, else the state and its shots are put back.
  bool TryStep(const StaticLoads& loads, double norm, bool chord_steps = false);
  void RecordStates();

  Assembly assembly_;
  AssemblyOptions options_;
  Mode mode_ = Mode::kForward;
  std::vector<Rod> rods_;
  Eigen::VectorXd x_;  ///< 6 base unknowns per rod, scaled
  std::vector<lie::SE3> poses_;
  std::vector<double> lengths_;
  std::vector<double> body_force_scale_, body_moment_scale_;
  std::vector<RodState> states_;
  bool states_dirty_ = true;
  bool has_solution_ = false;
  // Workspace of the Levenberg–Marquardt iterations (sized on first use).
  Eigen::VectorXd r_, r_trial_, dz_;
  Iterate saved_;  ///< the point before a trial step
  /// The share of the bodies' applied force and moment in force (the continuation from an
  /// unloaded start ramps it; 1 otherwise).
  double body_load_factor_ = 1.0;
  StaticLoads shot_loads_;  ///< the loads the rods' samples hold (RodShot::SetLoads)
  bool shot_loads_set_ = false;
  Eigen::MatrixXd J_, A_;
  Eigen::MatrixXd inverse_;  ///< the quasi-Newton estimate of J⁻¹ (Broyden)
  Eigen::VectorXd broyden_y_, broyden_Hy_, broyden_sH_;  ///< the update's vectors
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  /// The mode whose Jacobian lu_ holds (none yet: a mode that never occurs).
  Mode jacobian_mode_ = static_cast<Mode>(-1);
  StaticLoads solved_loads_;
};

}  // namespace cosserat
