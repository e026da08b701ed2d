#pragma once
/// \file
/// The SE(3) strong form (FD notes 2025, eqs. 14, 16, 19–20) linearised about a static equilibrium
/// of the cantilever or of a column (ShootingEnds), in the frequency domain.
///
/// A perturbation g = g₀ Exp(η̂) with η = [θ; u] (body frame, rad; m) and W = W₀ + δW, harmonic
/// in time with circular frequency ω (V₀ = 0, so δV = η_t and δV_t = −ω² η), obeys the linear
/// ODE in s (ξ₀ = [K; Γ], W₀ = [m; n], f_W the distributed force per length):
///   θ'  = δK − K × θ,            u'  = δΓ − K × u − Γ × θ          (δξ = η' + ad_ξ₀ η)
///   δm' = δm × K + m × δK + δn × Γ + n × δΓ − ω² J θ
///   δn' = δn × K + n × δK + θ × (R₀ᵀ f_W) − R₀ᵀ δf_W − ω² ρA u,   δξ = K(s)⁻¹ δW
/// where δf_W is the change of the loads that depend on the pose (contact, a current's drag at
/// rest) with δp = R₀ u and δt = R₀ (θ × e₃), and f_W includes them as the static solver does.
/// with θ(0) = u(0) = 0 at the clamp and δW(0) the 6 unknowns (a pinned base: ShootingEnds). The
/// free tip's condition
/// W(L) = [R(L)ᵀ M_W; R(L)ᵀ F_W] (world loads; body loads are constant) linearises to
///   B(ω) δW(0) = [δm − (R₀ᵀ M_W) × θ;  δn − (R₀ᵀ F_W) × θ](L) = 0,
/// so det B(ω) = 0 exactly at a natural frequency, and the null vectors give the mode shapes.
/// A rigid body at the free tip (mass m_b, principal inertia J_b in the tip's body frame) adds
/// its inertia, W(L) = loads + ω² [J_b θ; m_b u](L): B's rows get − ω² J_b θ and − ω² m_b u.
/// RK4 on the grid, with the equilibrium re-integrated on the same stages as the statics solver.
/// At ω = 0, B is the statics Jacobian (in rotation-vector instead of matrix coordinates).

#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/lie/types.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat {

/// The ends a perturbation obeys: the cantilever's (a clamped base, a free tip), or a column's
/// (a pinned or clamped base; a tip guided along the column's axis, which carries its dead axial
/// load, pinned or clamped there).
struct ShootingEnds {
  /// The base turns about its body x and y (θ(0) = [a, b, 0]) and holds the twist: its unknowns
  /// are those turns, the torque about the axis and the force, δm(0) = [0, 0, c].
  bool base_pinned = false;
  /// The tip moves along the column's axis only: rows e_x·δp = e_y·δp = 0 and
  /// e·δ(n_W − F_W) = 0, with the moments (pinned) or R θ (clamped) as the other three.
  bool tip_guided = false;
  bool tip_clamped = false;
  /// The column's frame, world: its third column the axis (the problem's base.rotation).
  Mat3 axes_W = Mat3::Identity();
  /// A rigid body at a free tip (not with tip_guided): its mass, kg, and its principal moments
  /// of inertia about the tip section's body axes, kg·m². Its weight is the loads' (a dead tip
  /// force); here it adds its inertia only.
  double tip_mass = 0.0;
  Vec3 tip_inertia = Vec3::Zero();
};

class FrequencyShooting {
 public:
  using Mat12 = Eigen::Matrix<double, 12, 12>;

  /// Linearises about the equilibrium whose base wrench W(0) = [m; n] (base body frame, N·m; N)
  /// is `base_wrench_B` (StaticShootingSolver::base_wrench_B() of a converged solve on the same
  /// grid). Throws std::invalid_argument for rods with tendons. A column's `base` is the frame
  /// of its first node (a pinned base's is turned) and `base_wrench_B` the wrench there.
  FrequencyShooting(const RodModel& rod, const std::vector<double>& grid, const lie::SE3& base,
                    const StaticLoads& loads, const Vec6& base_wrench_B,
                    const Actuation& actuation = {}, const ShootingEnds& ends = {});

  /// The dimensionless boundary matrix: S_r⁻¹ B(ω) S_u with S = diag(EI/L ×3, EI/L² ×3), so the
  /// unknowns and the residual are scaled as in the statics solver (a pinned base's turns in
  /// rad; a guided tip's displacements over L, its clamped rotation in rad).
  Mat6 BoundaryMatrix(double omega) const;

  /// The node values of the perturbation started from the dimensionless unknown x (δW(0) =
  /// S_u x): displacement R₀ u (world, m) and rotation R₀ θ (world, rad).
  void Shape(double omega, const Vec6& x, std::vector<Vec3>* displacement_W,
             std::vector<Vec3>* rotation_W) const;

  /// The same linearisation read at ω² = −σ²: its "frequencies" are the growth rates σ (1/s)
  /// of the unstable directions, e^{σ t}, of an equilibrium past a critical load.
  FrequencyShooting GrowthRates() const {
    FrequencyShooting g = *this;
    g.sign_ = -1.0;
    return g;
  }

  const std::vector<double>& grid() const { return grid_; }
  /// Equilibrium rotation R_WB at the nodes.
  const std::vector<Mat3>& rotation_WB() const { return node_R_; }
  /// EI of the section at s = 0 (N·m²), the larger principal value.
  double bending_stiffness() const { return EI_; }
  double mass_per_length_at_base() const { return rhoA0_; }

 private:
  // A(s) = A0 − ω² A1 at one RK4 stage; A1 has only the J θ and ρA u entries.
  struct Stage {
    Mat12 a0;
    Vec3 J;  // ρ I per length, kg·m
    /// Translational mass per length in the body frame, kg/m: ρA, plus a fluid's added mass on
    /// the two directions normal to the rod.
    Vec3 mass = Vec3::Zero();
  };
  template <typename Visit>
  Eigen::Matrix<double, 12, 6> Integrate(double omega, const Eigen::Matrix<double, 12, 6>& z0,
                                         Visit&& visit) const;
  /// The perturbation at s = 0 of each dimensionless unknown (its columns).
  Eigen::Matrix<double, 12, 6> Start() const;

  std::vector<double> grid_;
  std::vector<Stage> stages_;  // 4 per segment: start, mid, mid, end
  std::vector<Mat3> node_R_;
  Mat3 tip_moment_cross_ = Mat3::Zero(), tip_force_cross_ = Mat3::Zero();  // (R₀ᵀ M_W)^, ...
  Vec6 scale_;
  ShootingEnds ends_;
  /// The equilibrium's n(L) less the tip force's follower part, body frame, N
  Vec3 tip_force_B_ = Vec3::Zero();
  double EI_ = 0, rhoA0_ = 0;
  double sign_ = 1.0;  ///< of ω² in A(s) = A0 − ω² A1: −1 for GrowthRates
};

}  // namespace cosserat
