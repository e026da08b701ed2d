#pragma once
/// \file
/// Dynamics of an Assembly (assembly.hpp): its rods on the SE(3) strong form with BDF2 in time
/// (one Bdf2ShootingStepper per rod, cantilevered at its base, its tip held by the body it is
/// joined to: TipHold), and its rigid bodies by the Newton–Euler equations with the same BDF2
/// weights. The junction conditions of the applications chapter of the source (eq. 10.1):
///   m a_W  = m g + F + Σ (rod ends' forces on the body)                       (world)
///   J α + ω × J ω = Rᵀ (M + Σ (rod ends' moments about the body's origin))   (body frame)
/// with a_W, α the BDF2 rates of the body's world velocity and body angular velocity, and those
/// the BDF2 rates of its pose: v_W = c0 p + c1 p₁ + c2 p₂, ω = c1 Log(Rᵀ R₁) + c2 Log(Rᵀ R₂).
/// A rod's base on a body moves with it (pose and twist); a rod's tip joined to a body is held
/// at the attachment frame, so a rod's step gives the wrench its ends put on the bodies.
///
/// The unknowns of a step are the bodies' poses (6 each); each evaluation of the balance steps
/// every rod from its last accepted state to those poses. Newton on the poses with a
/// forward-difference Jacobian, kept across steps while it converges. Linear momentum: the rods'
/// world-frame forces and the bodies' BDF2 rates make the total exact up to the solves'
/// tolerances. Rods held in the world are clamped there; torsion-free bases are statics only.

#include <chrono>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "cosserat/assembly/assembly.hpp"
#include "cosserat/assembly/assembly_statics.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

struct AssemblyDynamicsOptions {
  double dt = 2e-3;  ///< s
  /// Convergence of a step: the 2-norm of the bodies' balance, forces over their rods' largest
  /// EI/L² and moments over EI/L (as in statics). The rods' own steps solve to rod.tolerance,
  /// which must be tighter: their error is noise in this balance.
  double tolerance = 1e-8;
  int max_iterations = 20;  ///< Newton iterations per step
  /// The statics of InitializeAtRest (the start at rest).
  AssemblyOptions statics;
  /// The rods' steppers: scheme, pieces, first step. Their dt is dt; their halvings are off (a
  /// rod's sub-steps would not be the bodies' steps).
  Bdf2Options rod = [] {
    Bdf2Options o;
    o.tolerance = 1e-12;
    return o;
  }();
};

/// Linear momentum and angular momentum about the world origin (world), and energy (J) of the
/// whole assembly: rods and bodies.
struct AssemblyMomentum {
  Vec3 linear_W = Vec3::Zero();
  Vec3 angular_W = Vec3::Zero();
};

class AssemblyDynamics {
 public:
  /// Throws std::invalid_argument for an invalid assembly or options, or a torsion-free base.
  explicit AssemblyDynamics(const Assembly& assembly, const AssemblyDynamicsOptions& options = {});

  /// At rest in equilibrium under `loads` and the bodies' applied loads, at t = 0. A structure
  /// held in the world is solved by AssemblyStaticsSolver first and refined on the steppers'
  /// equations; a free-floating one starts from the bodies' given poses, which must already be
  /// an equilibrium.
  AssemblySummary InitializeAtRest(const StaticLoads& loads);

  /// Advances by dt under `loads` (distributed loads on the rods, gravity on all) and the
  /// bodies' applied loads (SetBodyLoad). On failure the state stays at the last step.
  AssemblySummary Step(const StaticLoads& loads);

  /// The load applied at body b's origin from now on (world, N and N·m).
  void SetBodyLoad(int b, const Vec3& force_W, const Vec3& moment_W);

  double time() const { return time_; }
  const lie::SE3& body_pose(int b) const { return bodies_[b].now.pose; }
  const Vec3& body_velocity_W(int b) const { return bodies_[b].now.velocity_W; }
  const Vec3& body_angular_velocity_B(int b) const { return bodies_[b].now.omega_B; }
  const Bdf2ShootingStepper& rod(int i) const { return *rods_[i]; }
  int rod_count() const { return static_cast<int>(rods_.size()); }
  /// The rod whose own solve failed last (its stepper, at the bodies' trial poses), −1 if none
  /// since the last InitializeAtRest or Step began, with that solve's summary.
  int failed_rod() const { return failed_rod_; }
  const StepSummary& failed_rod_summary() const { return failed_rod_summary_; }
  int body_count() const { return static_cast<int>(bodies_.size()); }

  AssemblyMomentum Momentum() const;
  /// Kinetic, elastic and gravity's potential energy of rods and bodies (J): the rods' by their
  /// steppers' quadrature, the bodies' with their BDF2 velocities.
  double Energy(const StaticLoads& loads) const;

 private:
  /// A body's pose and BDF2 velocities at one time.
  struct Kinematics {
    lie::SE3 pose;
    Vec3 velocity_W = Vec3::Zero();  ///< of its origin, m/s
    Vec3 omega_B = Vec3::Zero();     ///< rad/s, body frame
  };
  struct Body {
    Kinematics now, before;  ///< at t_n and t_{n−1}
    Kinematics trial;        ///< at t_{n+1}, for the unknowns being tried
    double force_scale = 1.0, moment_scale = 1.0, length_scale = 1.0;
  };
  /// Puts the trial poses at z (6 per body: δp over the body's length scale, δθ in rad, body
  /// frame) from `from`, with their BDF2 velocities for weights c (statics: zero).
  void SetTrialPoses(const Eigen::VectorXd& z, const std::vector<lie::SE3>& from,
                     const Bdf2ShootingStepper::Coefficients& c, bool statics);
  /// The input of rod i's step at the trial poses.
  StepInput RodInput(int i, const StaticLoads& loads) const;
  /// Steps (or, in statics, puts at rest) every rod at the trial poses and writes the bodies'
  /// scaled balance. False when a rod fails.
  bool Balance(const StaticLoads& loads, const Bdf2ShootingStepper::Coefficients& c, bool statics,
               Eigen::VectorXd* r);
  /// Newton on the trial poses from z = 0 around `from`. On success the rods hold the solution.
  bool Solve(const StaticLoads& loads, const std::vector<lie::SE3>& from,
             const Bdf2ShootingStepper::Coefficients& c, bool statics, AssemblySummary* summary);
  /// The forward-difference Jacobian of Balance at z (r its value there), factorised.
  bool RenewJacobian(const StaticLoads& loads, const std::vector<lie::SE3>& from,
                     const Bdf2ShootingStepper::Coefficients& c, bool statics,
                     const Eigen::VectorXd& z, const Eigen::VectorXd& r);

  Assembly assembly_;
  AssemblyDynamicsOptions options_;
  std::vector<std::unique_ptr<Bdf2ShootingStepper>> rods_;
  int failed_rod_ = -1;
  StepSummary failed_rod_summary_;
  std::vector<Bdf2ShootingStepper::Snapshot> accepted_;  ///< each rod's last accepted step
  std::vector<Vec6> base_wrench_guess_;  ///< each rod's W(0), for its static solves
  /// Each rod's equilibrium from the statics solver (empty when no rod is held by the ground):
  /// the start of its static solves, whose junctions it places when the rod is shot in pieces.
  std::vector<RodState> statics_states_;
  std::vector<Body> bodies_;
  double time_ = 0.0, last_dt_ = 0.0;
  bool initialized_ = false;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  double jacobian_c0_ = -1.0;  ///< the c0 the factors are for; −1: none
  bool jacobian_statics_ = false;
};

}  // namespace cosserat
