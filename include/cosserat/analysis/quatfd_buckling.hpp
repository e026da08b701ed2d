#pragma once
/// \file
/// Buckling on the quaternion finite-difference model (Lang & Linn 2009): the critical load along a
/// load path where the static stiffness of the discrete rod stops being positive definite.
///
/// The equilibrium is followed along loads(λ) = fixed + λ · per_unit with the quaternion-FD Newton
/// statics (quatfd_statics.hpp), warm-started. At each equilibrium the static stiffness is the
/// Hessian of the discrete potential energy on the constraint manifold |p| = 1: the derivative of
/// the generalised forces (vertex forces, N, world; segment body torques, N·m) with respect to the
/// tangent coordinates (vertex displacements δx, world, m; segment rotations δθ with
/// p ← p ⊗ [cos(|δθ|/2), sin(|δθ|/2) δθ/|δθ|], body frame, rad). Scaled by ξ = δx/L and divided
/// by EI/L it is dimensionless. By default it comes from the model's exact banded Jacobian ∂f/∂q
/// at v = 0
/// (no Baumgarte terms): f = M⁻¹ × forces, so the vertex rows are the forces over the lumped masses
/// and the quaternion rows p ⊗ [0, ½ J⁻¹τ]; at an equilibrium (f = 0) the forces' derivative is
/// m ∂f_x/∂q and 2 J Im(p̄ ⊗ ∂f_p/∂q), taken along the tangent directions ∂q/∂δx and
/// ∂p/∂δθ = ½ p ⊗ [0, e_k]; central differences of QuatFdModel::Forces along exact retractions
/// are the cross-check (finite_difference_stiffness). Its smallest eigenvalue μ(λ) changes sign
/// where the equilibrium loses stability, whether the root is simple or double (a rod symmetric
/// about its axis buckles in two planes at once; det would touch zero without changing sign, an
/// eigenvalue does not). The scan brackets the sign change of μ and the Illinois variant of regula
/// falsi refines it.
///
/// Needs a clamped base (a pinned–free rod is a mechanism: μ ≡ 0) and conservative loads: dead tip
/// force and moment in the world frame, gravity, distributed force. Tendon tension and pressure
/// paths need a new model at every λ and are not supported here (use BucklingAnalysis).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "cosserat/analysis/buckling.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"

namespace cosserat {

struct QuatFdBucklingOptions {
  double lambda_max = 1.0;  ///< the largest λ searched (load units, see LoadPath)
  int scan_steps = 40;      ///< equal steps from 0 to lambda_max (a failed step is halved)
  /// Refinement stops when the bracket is narrower than this fraction of λ_cr.
  double lambda_tolerance = 1e-9;
  /// Central-difference step of the stiffness: rotations in rad, displacements in units of L.
  /// The truncation error is O(h²) ≈ 1e-10 relative; round-off in the axial forces (EA up to
  /// 1e5 EI/L² for a slender rod) over 2h gives ≈ 1e-6 EI/L in an entry.
  double fd_step = 1e-5;
  /// The stiffness from the model's exact banded ∂f/∂q (default), or by central differences of
  /// the forces (fd_step; the cross-check).
  bool finite_difference_stiffness = false;
  /// The most any segment may turn between two points of the path, rad: a solve that turns one
  /// further jumped to another branch, and its step is halved.
  double max_turn = 0.3;
  quatfd::QuatFdStaticsOptions statics;

  /// On failure writes "<field>: <why>".
  bool IsValid(std::string* why) const;
};

struct QuatFdBucklingSummary {
  BucklingStatus status = BucklingStatus::kNotRun;
  double critical_load = NAN;  ///< λ_cr (load units); NaN unless found
  double lambda_reached = 0;   ///< the last λ where statics converged
  /// Eigenvalues of the stiffness within 1e-4 μ(0) of zero at λ_cr: the multiplicity of the root
  /// (2: a double root, any plane buckles alike). The threshold sits far above the difference
  /// error (≈ 1e-6 EI/L) and far below the next mode's eigenvalue (the second cantilever Euler load
  /// is 9 times the first).
  int multiplicity = 0;
  /// Where the mode (the eigenvector of the smallest eigenvalue at λ_cr) bends most: the first
  /// vertex of largest |δK⊥|, δK_n ≈ (δθ_{n+1/2} − δθ_{n−1/2})/(s_{n+1/2} − s_{n−1/2}) (the clamp's
  /// δθ is zero), m. NaN unless found.
  double mode_s_max = NAN;
  std::vector<double> scan_lambda;          ///< the scan: λ …
  std::vector<double> scan_min_eigenvalue;  ///< … and μ(λ) (dimensionless, units EI/L)
  int solves = 0;                           ///< static solves
  double wall_time_s = 0;
  /// With kPreloadPastCritical: the stiffness eigenvalues below zero at λ = 0 (its unstable
  /// directions under the fixed loads alone).
  int preload_unstable_directions = 0;
  bool found() const { return status == BucklingStatus::kFound; }
};

class QuatFdBuckling {
 public:
  /// Throws std::invalid_argument naming the field: "base_end" (not clamped), "tip_force_frame" /
  /// "tip_moment_frame" (follower loads), "load path" (tension or pressure), options' fields.
  QuatFdBuckling(const RodModel& rod, const lie::SE3& base, const LoadPath& path,
                 const quatfd::QuatFdOptions& model_options,
                 const QuatFdBucklingOptions& options = {});

  /// Scan and refine. Leaves q() at the pre-buckled equilibrium at λ_cr (or the last λ reached).
  QuatFdBucklingSummary FindCriticalLoad();

  /// The eigenvalues (ascending, dimensionless: units EI/L with δx in units of L) of the
  /// symmetric part of the static stiffness at q under the loads of λ: one banded Jacobian (or
  /// two Forces evaluations per tangent coordinate), then a dense symmetric eigenvalue problem
  /// (6N unknowns for N segments).
  /// With `vectors`, also the eigenvectors (columns, in the tangent coordinates [δx/L of the free
  /// vertices; δθ of the segments]).
  Eigen::VectorXd StiffnessEigenvalues(double lambda, const Eigen::VectorXd& q,
                                       Eigen::MatrixXd* vectors = nullptr);
  /// The number of eigenvalues of the same symmetric stiffness below −below (units EI/L): the
  /// inertia of its shift by an LDLᵀ factorisation in the tangent coordinates ordered along the
  /// rod, where it is banded (O(N) instead of the eigenvalues' O(N³)); by the eigenvalues when a
  /// pivot is too small to trust, and −1 then if there are more than kMaxDenseStiffness
  /// coordinates. With finite_difference_stiffness, by the eigenvalues always.
  int StiffnessEigenvaluesBelow(double lambda, const Eigen::VectorXd& q, double below);
  /// The most tangent coordinates whose stiffness is worth an eigenvalue fallback (401 nodes:
  /// 0.5 s).
  static constexpr int kMaxDenseStiffness = 2400;
  /// The largest |H − Hᵀ| / |H| of the last stiffness computed (a check: conservative loads
  /// give a symmetric Hessian up to the difference error).
  double last_asymmetry() const { return asymmetry_; }
  /// The stiffness matrix itself (for the cross-check of the two ways of computing it).
  Eigen::MatrixXd Stiffness(double lambda, const Eigen::VectorXd& q, bool finite_difference);

  const Eigen::VectorXd& q() const { return q_; }
  const quatfd::QuatFdModel& model() const { return model_; }

 private:
  /// Statics at λ from `start`; on the path (the default), a solve that turns a segment by more
  /// than max_turn counts as failed.
  bool SolveAt(double lambda, const Eigen::VectorXd& start, Eigen::VectorXd* q,
               bool on_path = true);
  struct Bracket;
  /// Narrows the bracket of the stability loss to lambda_tolerance (FindCriticalLoad).
  void RefineBracket(Bracket* bracket);
  /// s (m) of the vertex where the buckling mode at (λ, q) bends most.
  double ModeMaxCurvatureS(double lambda, const Eigen::VectorXd& q);

  quatfd::QuatFdModel model_;
  LoadPath path_;
  QuatFdBucklingOptions options_;
  /// The stiffness matrix H' (dimensionless, tangent coordinates) at q under the loads of λ.
  Eigen::MatrixXd StiffnessFiniteDifference(const Eigen::VectorXd& q);
  Eigen::MatrixXd StiffnessAnalytic(const Eigen::VectorXd& q);
  /// The same from the banded ∂f/∂q without a dense step: O(N).
  Eigen::SparseMatrix<double> StiffnessAnalyticSparse(const Eigen::VectorXd& q);

  std::vector<int> free_vertices_;  ///< vertices whose position is not prescribed
  Eigen::VectorXd q_, zero_v_, forces_plus_, forces_minus_;
  BandedMatrix dfdq_, dfdv_;
  double asymmetry_ = 0;
  int solves_ = 0;
};

}  // namespace cosserat
