#pragma once
/// \file
/// The semi-discrete quaternion finite-difference Cosserat rod of Lang & Linn 2009, as an
/// index-1 second-order ODE q̈ = f(q, q̇) (their eq. 4 with the multipliers eliminated).
///
/// Staggered grid: vertices 0 = s_0 < … < s_N = L carry the centroids x_n (world, m); the
/// segment midpoints s_{n+1/2} carry quaternions p_{n+1/2} = [w, x, y, z] whose rotation R(p)
/// maps the section (body) frame to the world (body z = rod tangent at rest).
///   Γ_{n+1/2} = R(p)ᵀ (x_{n+1} − x_n)/Δs      (strain [shear1, shear2, stretch], their eq. 1)
///   K_n = K(p_{n−1/2}, p_{n+1/2})            (curvature [bend1, bend2, twist] at vertex n)
///   F = C_Γ (Γ − Γ*) + C̃_Γ Γ̇,  M = C_K (K − K*) + C̃_K K̇  (Antman viscoelastic laws)
/// The forces are the negative gradients of the discrete strain energy (plus the Rayleigh damping
/// forces), so the discrete model conserves energy without damping.
///
/// Unknown ordering (one block of 7 per vertex + segment): q = [x_0, p_{1/2}, x_1, p_{3/2}, …,
/// p_{N−1/2}, x_N], size 7N + 3; v = q̇ in the same order. With this ordering ∂f/∂q and ∂f/∂v
/// have lower and upper bandwidth 10 (Lang & Linn 2009: "bandwidths equal to ten").
///
/// Ends: s = 0 is clamped (x_0 and the orientation fixed: the curvature at vertex 0 is taken
/// between the clamp's quaternion and p_{1/2} over Δs/2, which is the ghost-point scheme with
/// p_{−1/2} mirrored through the clamp), pinned (x_0 fixed, zero moment) or free (zero force and
/// moment). s = L is free (zero moment: no bending element at vertex N; the tip loads) or pinned
/// at a given point (x_N held there, zero moment: cables, risers and moorings between anchors).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/lie/types.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/quatfd_kernels.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::quatfd {

/// The discrete curvature K_n at an interior vertex from p_a = p_{n−1/2}, p_b = p_{n+1/2}, with
/// r = p̄_a p_b = [cos(θ/2), sin(θ/2) u] for a relative rotation by θ about u, h = s_b − s_a.
enum class Curvature {
  /// K = 2 Im(r)/h = (2/h) sin(θ/2) u (the vertex quaternion is the mean of its neighbours).
  /// Cheapest; second order. The moment stops growing at θ = π and falls beyond, and K scales
  /// with |p_a| |p_b|, so constraint drift changes the stiffness.
  kBasic,
  /// Variant 1 (default): K = 2 Im(p̄_n p'_n)/|p_n|² for p_n = (p_a+p_b)/2, p'_n = (p_b−p_a)/h,
  /// the exact curvature of the linearly interpolated quaternion field, = (4/h) tan(θ/4) u for
  /// unit quaternions. Unchanged when both quaternions are scaled alike (drift does not change the
  /// stiffness), monotone in θ up to 2π, no roots or trigonometric functions; second order.
  kVariant1,
};

enum class EndCondition {
  kClamped,  ///< position and orientation prescribed (s = 0 only)
  kPinned,   ///< position prescribed, rotation free, zero moment
  kFree,     ///< zero force and moment (tip loads act at s = L)
};

struct QuatFdOptions {
  int segments = 20;  ///< N ≥ 2
  /// Optional explicit vertices 0 = s_0 < … < s_N = L (m), for non-equidistant grids; when set,
  /// it must have segments + 1 strictly increasing entries from 0 to the rod length. Empty: the
  /// uniform grid of MakeGrid (profile breakpoints become vertices).
  std::vector<double> grid;
  Curvature curvature = Curvature::kVariant1;
  EndCondition base_end = EndCondition::kClamped;  ///< the end at s = 0
  /// A pinned base that holds the twist about the rod's axis (a clevis, a universal joint): the
  /// clamp's element at s = 0 with its torsional part only. Without it, a rod pinned at both ends
  /// is free to spin about its own line (an isotropic section stores no energy in that).
  bool base_twist_held = false;
  EndCondition tip_end = EndCondition::kFree;      ///< the end at s = L
  /// Where a pinned or clamped tip is held (world, m).
  Vec3 tip_position_W = Vec3::Zero();
  /// A clamped tip's rotation R_WB (its third column the rod's tangent at s = L): the clamp's
  /// element at s = L, the mirror of the base's.
  Mat3 tip_rotation_W = Mat3::Identity();
  /// Whether the tip is held at tip_position_W (pinned or clamped).
  bool TipHeld() const { return tip_end != EndCondition::kFree; }
  /// A held tip that moves as tip_position_W + A (1 − cos ω t) (a vessel's heave and surge,
  /// setting off from rest at tip_position_W and swinging about tip_position_W + A; A in m,
  /// world; ω in rad/s; 0: held still). The model has no time: the tip vertex is driven as the
  /// oscillator ẍ = −ω² (x − tip_position_W − A), which from rest at tip_position_W follows that
  /// motion as exactly as the integrator integrates it. Statics and modes hold it at
  /// tip_position_W. (A start at rest spares the rod the velocity jump of a sine, whose axial
  /// waves cost a 1 km riser 7 times more Radau steps.)
  Vec3 tip_motion_amplitude = Vec3::Zero();
  double tip_motion_angular_frequency = 0.0;

  /// Baumgarte stabilisation of g = (|p|² − 1)/2: g̈ + 2α ġ + β² g = 0 (1/s). Zero: g̈ = 0 and
  /// the integrators project onto |p| = 1 after each step instead.
  double baumgarte_alpha = 0.0;
  double baumgarte_beta = 0.0;

  /// Checks the fields; on failure writes "<field>: <why>".
  bool IsValid(std::string* why) const;
};

/// Layout of the unknowns (see the file comment).
struct QuatFdLayout {
  int segments = 0;
  int size() const { return 7 * segments + 3; }
  static int X(int n) { return 7 * n; }        ///< first index of x_n
  static int P(int nu) { return 7 * nu + 3; }  ///< first index of p_{ν+1/2}, ν = 0..N−1
  static constexpr int kBandwidth = 10;
};

/// Energies of a state (J).
struct QuatFdEnergy {
  /// kinetic: the rod's, and the fluid's added mass moving with the vertices' velocity across
  /// the centreline;
  /// potential: of the distributed dead loads (gravity, distributed force);
  /// loads: −work of the dead tip force
  double kinetic = 0, elastic = 0, potential = 0, loads = 0;
  double total() const { return kinetic + elastic + potential + loads; }
};

class QuatFdModel {
 public:
  /// Samples the rod on MakeGrid's grid with options.segments segments (profile breakpoints
  /// become vertices). `base` is the clamp pose (R_WB, p_W of s = 0): for kClamped both are used,
  /// for kPinned the position, for kFree only the initial state. Throws std::invalid_argument
  /// naming the field when the rod, the options or the actuation are invalid, and for a tendon
  /// under tension: this path models chambers' pressures, not tendons.
  QuatFdModel(const RodModel& rod, const lie::SE3& base, const QuatFdOptions& options,
              const Actuation& actuation = {});

  const QuatFdOptions& options() const { return options_; }
  const QuatFdLayout& layout() const { return layout_; }
  int size() const { return layout_.size(); }
  const std::vector<double>& grid() const { return s_; }
  double length() const { return s_.back(); }

  /// Loads are an input, not part of the constant model: set before evaluating. Lumps the
  /// distributed loads on the vertices (O(segments)).
  void set_loads(const StaticLoads& loads);
  const StaticLoads& loads() const { return loads_; }
  /// A gusting flow (loads/fluid.hpp) on the fluid of the loads set: the drag then follows the
  /// time last given to set_time, which the integrators set to each stage's time. Without a
  /// gust the model has no clock and set_time does nothing.
  void set_gust(const FluidGust& gust);
  void set_time(double t) const;

  /// The rest shape (the discrete configuration with Γ = Γ*, K = K*) from the base pose, at rest.
  /// With a pinned tip, a shape through both ends instead, the start of a static solve
  /// (HeldShape): the chord, stretched uniformly, when the ends are at least the rod's length
  /// apart; else the inextensible catenary of the rod's length hanging in the net distributed load
  /// of the loads set (weight less buoyancy, plus a uniform force; in gravity where that cancels),
  /// or a parabola bowed along the base frame's x when there is no load across the chord.
  /// Throws std::invalid_argument when q or v is not of size().
  void RestState(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> v) const;

  /// a = f(q, v) = q̈ (Lang & Linn 2009, eq. 4). Prescribed vertices get a = 0.
  void Acceleration(const Eigen::Ref<const Eigen::VectorXd>& q,
                    const Eigen::Ref<const Eigen::VectorXd>& v,
                    Eigen::Ref<Eigen::VectorXd> a) const;

  /// ∂f/∂q and ∂f/∂v, exact, banded (kl = ku = 10; the matrices are resized and overwritten).
  /// Hand-derived element Jacobians (quatfd_kernel_jacobians.hpp) assembled band-wise and chained
  /// through the quaternion mass-matrix inverse. Optionally also f.
  void Jacobian(const Eigen::Ref<const Eigen::VectorXd>& q,
                const Eigen::Ref<const Eigen::VectorXd>& v, BandedMatrix* dfdq, BandedMatrix* dfdv,
                Eigen::VectorXd* a = nullptr) const;

  /// Same, with the Baumgarte parameters given instead of the options' (statics uses β > 0 to
  /// make the equilibrium equations regular in the normal direction of each quaternion).
  void Acceleration(const Eigen::Ref<const Eigen::VectorXd>& q,
                    const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                    Eigen::Ref<Eigen::VectorXd> a) const;
  void Jacobian(const Eigen::Ref<const Eigen::VectorXd>& q,
                const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                BandedMatrix* dfdq, BandedMatrix* dfdv, Eigen::VectorXd* a) const;
  /// The same Jacobian by forward-mode automatic differentiation (ceres::Jet) of the element
  /// kernels that give f: the test oracle for the analytic one.
  void JacobianAutoDiff(const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                        BandedMatrix* dfdq, BandedMatrix* dfdv, Eigen::VectorXd* a) const;

  /// The generalised forces behind f: rows X(n) get the total force on vertex n (N, world; zero
  /// at prescribed vertices), rows P(ν)+1..+3 the body torque on segment ν (N·m), rows P(ν) zero.
  void Forces(const Eigen::Ref<const Eigen::VectorXd>& q,
              const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> forces) const;

  /// Projection onto the constraint manifold: p ← p/|p|, ṗ ← (ṗ − (p̂·ṗ) p̂)/|p|, which keeps the
  /// rotation and ω (only the gauge |p|, p·ṗ is reset). Returns the largest
  /// | |p| − 1 | found before projecting.
  double Project(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> v) const;
  /// max over segments of | |p| − 1 |.
  double ConstraintViolation(const Eigen::Ref<const Eigen::VectorXd>& q) const;

  /// Whether unknown i is prescribed (the position of a clamped or pinned base vertex).
  bool IsFixed(int i) const { return fixed_[i]; }
  /// The piece of rod lumped on vertex n (its dual length, lumped mass and outer diameter), the
  /// site of the loads there (load.hpp).
  LoadSite VertexSite(int n) const {
    return {s_[n], vertex_weight_[n], mass_[n], vertex_diameter_[n]};
  }

  /// Node values for the writers: positions x_n; rotations at interior vertices from the
  /// normalised mean of the neighbouring quaternions, the clamp's at s = 0, p_{N−1/2} at a free
  /// tip; curvature K_n (zero at free/pinned ends); strain Γ and force averaged from the
  /// neighbouring segments; wrench W = [M; F] in the vertex's body frame (W(0) holds the support
  /// reaction's negative, so RodState::BaseReaction_W is the reaction); twist [ω; Rᵀ ẋ].
  void ToRodState(const Eigen::Ref<const Eigen::VectorXd>& q,
                  const Eigen::Ref<const Eigen::VectorXd>& v, RodState* state) const;

  QuatFdEnergy Energy(const Eigen::Ref<const Eigen::VectorXd>& q,
                      const Eigen::Ref<const Eigen::VectorXd>& v) const;

  /// Total mass (kg), and the lumped vertex masses.
  double Mass() const;
  const std::vector<double>& vertex_mass() const { return mass_; }
  /// The fluid's added mass on vertex n (kg, on the motion normal to the centreline direction
  /// there; zero without a fluid's added mass). Vertex n's mass matrix is
  /// m_n I + m_a,n (I − t tᵀ), t the direction of the chord between its neighbours.
  double vertex_added_mass(int n) const { return added_mass_.empty() ? 0.0 : added_mass_[n]; }
  /// The centreline direction at vertex n (world, unit): the chord between its neighbours,
  /// one-sided at the ends. The direction of the fluid loads and the added mass there.
  Vec3 VertexDirection(const Eigen::Ref<const Eigen::VectorXd>& q, int n) const;

  /// Smallest principal rotational inertia of a segment, ρ I Δs (kg·m²).
  double min_rotational_inertia() const;
  /// Principal rotational inertia of segment ν, diag(ρI1, ρI2, ρ(I1+I2)) Δs (kg·m², body frame).
  const Vec3& segment_inertia(int nu) const { return rotation_[nu].inertia; }

  /// Scales that make residuals dimensionless: EI/L (N·m) and EI/L² (N), EI the largest bending
  /// stiffness at s = 0.
  double moment_scale() const { return moment_scale_; }
  /// The largest |C_Γ (Γ − Γ*)| over the segments at rest in state q (N): the scale of the
  /// internal forces (a taut cable's tension).
  double MaxSegmentForce(const Eigen::Ref<const Eigen::VectorXd>& q) const;
  /// The largest entry of the segments' strain stiffness C_Γ (N): EA or κGA.
  double MaxStrainStiffness() const;
  /// The axial stiffness EA of the segments in series (N): L / Σ Δs/EA, what stretches a line
  /// of chain, rope and chain by the mean tension.
  double MeanAxialStiffness() const;
  double force_scale() const { return force_scale_; }

 private:
  /// The rotation of vertex n for the writers (ToRodState): the clamps' at clamped ends, the
  /// last segment's at a free or pinned tip, else the normalised mean of its two segments'.
  Vec4 VertexQuaternion(const Eigen::Ref<const Eigen::VectorXd>& q, int n) const;
  /// bend_ and bend_active_ for the grid, the ends and the actuation (constructor).
  void SetUpBendElements(const RodModel& rod, const Actuation& actuation);
  enum : int { kAutoDiff, kAnalytic };  ///< Evaluate's mode: J by Jet, by hand
  template <int kMode>
  void JacobianImpl(const Eigen::Ref<const Eigen::VectorXd>& q,
                    const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                    BandedMatrix* dfdq, BandedMatrix* dfdv, Eigen::VectorXd* a) const;
  /// f alone (Acceleration, Forces) in one pass, each segment's R(p), ω and 1/|p|² formed once.
  void EvaluateValue(const Eigen::Ref<const Eigen::VectorXd>& q,
                     const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                     Eigen::Ref<Eigen::VectorXd> a, bool forces_only) const;
  /// The forces-only result: rows of prescribed coordinates set to zero.
  void ZeroFixedRows(Eigen::Ref<Eigen::VectorXd> a) const {
    for (int r = 0; r < size(); ++r)
      if (fixed_[r]) a[r] = 0.0;
  }
  /// f with ∂f/∂q, ∂f/∂v (quatfd_model_jacobian.cpp): the force parts below, then ẍ = Q/m and
  /// p̈ from each segment's torque.
  template <int kMode>
  void Evaluate(const Eigen::Ref<const Eigen::VectorXd>& q,
                const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq, BandedMatrix* dfdv,
                bool forces_only) const;
  /// Evaluate's force parts with their derivatives (kAutoDiff or kAnalytic), added into the x rows
  /// (vertex forces, N, world) and rows P(ν)+1..+3 (body torques of segment ν, N·m) of a, and the
  /// same rows of dfdq, dfdv: the segments' stretch and shear, the bending/torsion elements,
  /// and the external loads.
  template <int kMode>
  void AddSegmentForces(const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> a,
                        BandedMatrix* dfdq, BandedMatrix* dfdv) const;
  template <int kMode>
  void AddBendTorques(const Eigen::Ref<const Eigen::VectorXd>& q,
                      const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> a,
                      BandedMatrix* dfdq, BandedMatrix* dfdv) const;
  template <int kMode>
  void AddLoads(const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::Ref<Eigen::VectorXd> a,
                BandedMatrix* dfdq) const;
  /// Replaces each segment's torque rows of a by its p̈ (4 rows from P(ν)) and chains the
  /// derivatives through ∂p̈/∂τ.
  template <int kMode>
  void AccelerateSegments(const Eigen::Ref<const Eigen::VectorXd>& q,
                          const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                          Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                          BandedMatrix* dfdv) const;
  /// Adds the external loads to the force rows of a: the distributed loads lumped on the
  /// vertices, the tip force on x_N (N, world) and the tip moment as a body torque on p_{N−1/2}.
  void AddExternalLoads(const Vec3& tip_force_W, const Vec3& tip_torque_B,
                        Eigen::Ref<Eigen::VectorXd> a) const;
  /// Adds the loads that depend on the motion (fluid drag) to the vertex rows of a, at each
  /// vertex's position, velocity and centreline direction t (from its neighbours); with dfdq and
  /// dfdv (or nullptr), their derivatives.
  void AddMotionLoads(const Eigen::Ref<const Eigen::VectorXd>& q,
                      const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> a,
                      BandedMatrix* dfdq, BandedMatrix* dfdv) const;
  /// Vertex forces to accelerations, ẍ = Q/m (prescribed vertices: 0); with dfdq, dfdv (or
  /// nullptr) their rows likewise. With a fluid's added mass, ẍ = M⁻¹ Q for the vertex mass
  /// matrix M = m I + m_a (I − t tᵀ), whose turning with t (a function of the neighbouring
  /// vertices) adds ∂(M⁻¹)/∂x Q to dfdq.
  void DivideVertexRowsByMass(const Eigen::Ref<const Eigen::VectorXd>& q,
                              Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                              BandedMatrix* dfdv) const;
  /// The chord between vertex n's neighbours (one-sided at the ends): its vertices a, b, its
  /// length |x_b − x_a| (m) and direction t (world, unit); ∂t/∂x_b = (I − t tᵀ)/|d| = −∂t/∂x_a.
  struct Chord {
    int a, b;
    double length;
    Vec3 t;
  };
  Chord VertexChord(const Eigen::Ref<const Eigen::VectorXd>& q, int n) const;
  /// The loads that depend on the motion (drag, contact) lumped on vertex n, world frame, N
  /// (zero without such loads).
  Vec3 VertexMotionForce_W(const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v, int n) const;
  /// The same for one vertex n with an added mass, at row r = X(n).
  void DivideVertexRowsByMassMatrix(const Eigen::Ref<const Eigen::VectorXd>& q, int n,
                                    Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                    BandedMatrix* dfdv) const;

  /// RestState's shape for a pinned tip.
  void HeldShape(Eigen::Ref<Eigen::VectorXd> q) const;
  /// Quaternion of the frame at s = L from p_{N−1/2} (free end).
  template <typename T>
  kernels::V4<T> TipQuaternion(const kernels::V4<T>& p_last) const;
  /// Tip force on x_N (N, world) and tip moment as a body torque on p_{N−1/2} (N·m).
  template <typename T>
  void TipLoads(const kernels::V4<T>& p_last, kernels::V3<T>* force_W,
                kernels::V3<T>* torque_B) const;
  /// TipLoads and its derivatives with respect to p_{N−1/2}.
  void TipLoadsJacobian(const Vec4& p_last, Vec3* force_W, Vec3* torque_B,
                        Eigen::Matrix<double, 3, 4>* force_p,
                        Eigen::Matrix<double, 3, 4>* torque_p) const;

  QuatFdOptions options_;
  QuatFdLayout layout_;
  Mat3 tip_compliance_ = Mat3::Identity();  ///< C_K⁻¹ at s = L
  Vec3 tip_rest_ = Vec3::Zero();            ///< K*(L)
  double tip_h_ = 0;                        ///< Δs_{N−1/2}
  lie::SE3 base_;
  Vec4 base_quat_;
  Vec4 tip_quat_ = Vec4(1, 0, 0, 0);  ///< a clamped tip's rotation (QuatFdOptions::tip_rotation_W)
  StaticLoads loads_;
  FluidGust gust_;
  mutable double time_ = 0.0;         ///< s, set_time's
  mutable StaticLoads gusty_loads_;   ///< loads_ with the gust's fluid at time_
  /// The loads the motion-dependent forces read: loads_, or with a gust its fluid at time_.
  const StaticLoads& motion_loads() const { return gust_.present() ? gusty_loads_ : loads_; }
  SplitWrench tip_wrench_;               ///< loads_ on the tip (dead: world, follower: tip frame)
  bool motion_loads_ = false;            ///< some load of loads_ depends on the motion (drag)
  std::vector<Vec3> vertex_force_W_;     ///< distributed loads lumped on each vertex, world, N
  std::vector<double> s_;                ///< vertices s_n, m
  std::vector<double> mass_;             ///< lumped vertex masses m_n, kg
  std::vector<double> added_mass_;       ///< the fluid's added mass per vertex, kg (empty: none)
  std::vector<double> vertex_weight_;    ///< dual lengths w_n, m
  std::vector<double> vertex_diameter_;  ///< outer diameter of the dual piece, m (fluid loads)

  std::vector<unsigned char> fixed_;                  ///< per unknown
  std::vector<kernels::SegmentConstants> segment_;    ///< per segment
  std::vector<kernels::RotationConstants> rotation_;  ///< per segment (inertia)
  std::vector<Vec3> inv_inertia_;                     ///< per segment, 1/inertia (f path)
  std::vector<kernels::BendConstants> bend_;          ///< per vertex; bend_active_ says which
  std::vector<unsigned char> bend_active_;
  double moment_scale_ = 1, force_scale_ = 1;
};

}  // namespace cosserat::quatfd
