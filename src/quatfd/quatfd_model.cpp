#include "cosserat/quatfd/quatfd_model.hpp"

#include <ceres/jet.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/lie/quaternion.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/quatfd/quatfd_kernel_jacobians.hpp"
#include "cosserat/rod/grid.hpp"

namespace cosserat::quatfd {
namespace {

using kernels::V3;
using kernels::V4;
using L = QuatFdLayout;

Mat3 Block(const Mat6& M, int r, int c) { return M.block<3, 3>(r, c); }

template <int M>
Eigen::Matrix<double, M, 1> Value(const Eigen::Ref<const Eigen::VectorXd>& x, int at) {
  return x.segment<M>(at);
}

// The f path's per-segment kernels for doubles (EvaluateValue): the formulas of AngularVelocity,
// SegmentForcesOmega and QuaternionAccelerationOmega (quatfd_kernels.hpp), with 1/|p|² formed
// once per segment and R(p) = H(p)/|p|² as a matrix, so a segment costs one division where the
// templated kernels (ToBody, ToWorld, ω, p̈ each dividing by |p|², ω̇ by J) took ~20. Equal to
// them up to round-off; the templated kernels stay the Jet oracle's.
struct SegmentFrame {
  double inv_n2;  ///< 1/|p|²
  Mat3 R;         ///< R(p), body → world
  Vec3 omega;     ///< body angular velocity 2 Im(p̄ ṗ)/|p|²
};

inline SegmentFrame Frame(const Vec4& p, const Vec4& pd) {
  SegmentFrame f;
  const double w = p[0], x = p[1], y = p[2], z = p[3];
  f.inv_n2 = 1.0 / p.squaredNorm();
  const double s = f.inv_n2, s2 = 2.0 * s;
  f.R << (w * w + x * x - y * y - z * z) * s, (x * y - w * z) * s2, (x * z + w * y) * s2,  //
      (x * y + w * z) * s2, (w * w - x * x + y * y - z * z) * s, (y * z - w * x) * s2,     //
      (x * z - w * y) * s2, (y * z + w * x) * s2, (w * w - x * x - y * y + z * z) * s;
  f.omega = s2 * kernels::ImConjMul<double>(p, pd);
  return f;
}

inline void SegmentForcesFrame(const kernels::SegmentConstants& c, const Vec3& dx, const Vec3& dv,
                               const SegmentFrame& f, Vec3* force_a, Vec3* torque) {
  const double inv = 1.0 / c.ds;
  const Vec3 gamma = f.R.transpose() * (dx * inv);
  const Vec3 gamma_dot = f.R.transpose() * (dv * inv) + gamma.cross(f.omega);
  const Vec3 F = c.stiffness * (gamma - c.rest) + c.damping * gamma_dot;
  *force_a = f.R * F;
  *torque = c.ds * gamma.cross(F);
}

inline Vec4 QuaternionAccelerationFrame(const Vec3& inertia, const Vec3& inv_inertia, double alpha,
                                        double beta, const Vec4& p, const Vec4& pd,
                                        const SegmentFrame& f, const Vec3& torque) {
  const double n2 = p.squaredNorm(), ppd = p.dot(pd);
  const Vec3& w = f.omega;
  const Vec3 wdot = (torque - w.cross(inertia.cwiseProduct(w))).cwiseProduct(inv_inertia);
  const Vec3 cv = 0.5 * n2 * wdot + ppd * w;
  const double c0 = -pd.squaredNorm() - 2.0 * alpha * ppd - 0.5 * beta * beta * (n2 - 1.0);
  return lie::QuatMultiply<double>(p, Vec4(c0, cv[0], cv[1], cv[2])) * f.inv_n2;
}

/// The vertices s_n (m): options.grid when given (checked: segments + 1 increasing values from 0
/// to the rod length), else ModelGrid's.
std::vector<double> VertexGrid(const RodModel& rod, const QuatFdOptions& options) {
  std::vector<double> s = ModelGrid(rod, options.segments + 1);  // throws for an invalid rod
  if (options.grid.empty()) return s;
  const std::vector<double>& g = options.grid;
  bool ok = static_cast<int>(g.size()) == options.segments + 1 && g.front() == 0.0 &&
            std::abs(g.back() - rod.length) <= 1e-12 * rod.length;
  for (size_t i = 1; ok && i < g.size(); ++i) ok = g[i] > g[i - 1];
  if (!ok)
    throw std::invalid_argument(
        "QuatFdOptions: grid: expected segments + 1 increasing values from 0 to the rod length");
  s = g;
  s.back() = rod.length;
  return s;
}

/// The chambers' shift of the rest curvature at s, K⁻¹ w (1/m, body frame): SectionLaw's rest
/// strain less the rod's own.
Vec3 ChamberShift(const RodModel& rod, double s, const Actuation& actuation) {
  if (rod.chambers.empty()) return Vec3::Zero();
  return (SectionLaw::At(rod, s, actuation).rest_strain - rod.RestStrainAt(s)).head<3>();
}

/// The bending/torsion element of interior vertex n, spanning [s_{n−1/2}, s_{n+1/2}]: its two
/// half cells act in series, so C_K = w (h1 C1⁻¹ + h2 C2⁻¹)⁻¹ with each half sampled at its own
/// midpoint (a stiffness jump at a vertex is then resolved to second order). The rest curvature
/// is ξ*(s_n) plus the halves' chamber shifts K⁻¹ w in series, (h1 δ1 + h2 δ2) / w
/// (SectionLaw): the rotation of the two halves adds up, so a chamber that ends at a vertex
/// counts for its half.
kernels::BendConstants InteriorBendElement(const RodModel& rod, const Actuation& actuation,
                                           const std::vector<double>& s, int n,
                                           kernels::CurvatureKind kind) {
  const double h1 = 0.5 * (s[n] - s[n - 1]), h2 = 0.5 * (s[n + 1] - s[n]);
  const double sa = s[n] - 0.5 * h1, sb = s[n] + 0.5 * h2;
  const SectionProperties a = PrincipalAxesSectionAt(rod, sa, actuation);
  const SectionProperties b = PrincipalAxesSectionAt(rod, sb, actuation);
  kernels::BendConstants c;
  c.h = c.weight = h1 + h2;
  const Mat3 Ca = Block(a.stiffness, 0, 0), Cb = Block(b.stiffness, 0, 0);
  c.stiffness = c.weight * (h1 * Ca.inverse() + h2 * Cb.inverse()).inverse();
  c.damping = (h1 * Block(a.damping, 0, 0) + h2 * Block(b.damping, 0, 0)) / c.weight;
  c.rest =
      rod.RestStrainAt(s[n]).head<3>() +
      (h1 * ChamberShift(rod, sa, actuation) + h2 * ChamberShift(rod, sb, actuation)) / c.weight;
  c.kind = kind;
  return c;
}

/// The one-sided element between p_{N−1/2} and a clamp at s = L: length Δs/2, its mirror.
kernels::BendConstants TipClampBendElement(const RodModel& rod, const Actuation& actuation,
                                           const std::vector<double>& s,
                                           kernels::CurvatureKind kind) {
  const int N = static_cast<int>(s.size()) - 1;
  const double h = 0.5 * (s[N] - s[N - 1]);
  const SectionProperties a = PrincipalAxesSectionAt(rod, s[N] - 0.5 * h, actuation);
  kernels::BendConstants c;
  c.h = c.weight = h;
  c.stiffness = Block(a.stiffness, 0, 0);
  c.damping = Block(a.damping, 0, 0);
  c.rest = rod.RestStrainAt(s[N]).head<3>() + ChamberShift(rod, s[N] - 0.5 * h, actuation);
  c.kind = kind;
  return c;
}

/// The one-sided element between a clamp at s = 0 and p_{1/2}: length Δs/2 (ghost point
/// p_{−1/2}).
kernels::BendConstants ClampBendElement(const RodModel& rod, const Actuation& actuation,
                                        const std::vector<double>& s, kernels::CurvatureKind kind) {
  const double h = 0.5 * (s[1] - s[0]);
  const SectionProperties a = PrincipalAxesSectionAt(rod, 0.5 * h, actuation);
  kernels::BendConstants c;
  c.h = c.weight = h;
  c.stiffness = Block(a.stiffness, 0, 0);
  c.damping = Block(a.damping, 0, 0);
  c.rest = rod.RestStrainAt(0.0).head<3>() + ChamberShift(rod, 0.5 * h, actuation);
  c.kind = kind;
  return c;
}

/// The element's torsional part alone: bending free, twist held (a pin that holds the twist).
kernels::BendConstants TwistOnly(kernels::BendConstants c) {
  const Eigen::Vector3d twist(0, 0, 1);
  c.stiffness = c.stiffness(2, 2) * twist * twist.transpose();
  c.damping = c.damping(2, 2) * twist * twist.transpose();
  return c;
}

}  // namespace

bool QuatFdOptions::IsValid(std::string* why) const {
  auto fail = [&](const std::string& msg) {
    if (why) *why = msg;
    return false;
  };
  if (segments < 2) return fail("segments: the quaternion-fd model needs at least 2 segments");
  if (tip_end == EndCondition::kClamped &&
      !((tip_rotation_W.transpose() * tip_rotation_W - Mat3::Identity()).norm() < 1e-9 &&
        tip_rotation_W.determinant() > 0))
    return fail("tip_rotation_W: a clamped tip needs a rotation matrix");
  if (!tip_position_W.allFinite()) return fail("tip_position_W: expected finite coordinates");
  if (!tip_motion_amplitude.allFinite())
    return fail("tip_motion_amplitude: expected finite coordinates");
  if (!(std::isfinite(tip_motion_angular_frequency) && tip_motion_angular_frequency >= 0))
    return fail("tip_motion_angular_frequency: expected a finite number >= 0");
  if (tip_motion_angular_frequency > 0 && !TipHeld())
    return fail("tip_motion_angular_frequency: moves a held tip (tip_end kPinned or kClamped)");
  if (!(std::isfinite(baumgarte_alpha) && baumgarte_alpha >= 0))
    return fail("baumgarte_alpha: expected a finite number >= 0");
  if (!(std::isfinite(baumgarte_beta) && baumgarte_beta >= 0))
    return fail("baumgarte_beta: expected a finite number >= 0");
  return true;
}

void QuatFdModel::SetUpBendElements(const RodModel& rod, const Actuation& actuation) {
  // Bending/torsion elements at the interior vertices, and at clamped ends (element 0 from the
  // base's clamp to p_{1/2}, element N from p_{N−1/2} to the tip's).
  const int N = layout_.segments;
  const auto kind = options_.curvature == Curvature::kBasic ? kernels::CurvatureKind::kBasic
                                                            : kernels::CurvatureKind::kVariant1;
  bend_.resize(N + 1);
  bend_active_.assign(N + 1, 0);
  for (int n = 1; n < N; ++n) {
    bend_[n] = InteriorBendElement(rod, actuation, s_, n, kind);
    bend_active_[n] = 1;
  }
  if (options_.tip_end == EndCondition::kClamped) {
    bend_[N] = TipClampBendElement(rod, actuation, s_, kind);
    bend_active_[N] = 1;
    tip_quat_ = lie::RotationToQuat(options_.tip_rotation_W);
  }
  if (options_.base_end == EndCondition::kClamped) {
    bend_[0] = ClampBendElement(rod, actuation, s_, kind);
    bend_active_[0] = 1;
  } else if (options_.base_end == EndCondition::kPinned && options_.base_twist_held) {
    bend_[0] = TwistOnly(ClampBendElement(rod, actuation, s_, kind));
    bend_active_[0] = 1;
  }
}

QuatFdModel::QuatFdModel(const RodModel& rod, const lie::SE3& base, const QuatFdOptions& options,
                         const Actuation& actuation)
    : options_(options), base_(base) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("QuatFdOptions: " + why);
  s_ = VertexGrid(rod, options);
  actuation.Require(static_cast<int>(rod.tendons.size()), static_cast<int>(rod.chambers.size()));
  for (size_t k = 0; k < rod.tendons.size(); ++k)
    if (actuation.tendon_tension[k] != 0.0)
      throw std::invalid_argument(
          "actuation.tendon_tension[" + std::to_string(k) +
          "]: the quaternion-FD model carries no tendon loads; a tendon's pull is solved by "
          "StaticShootingSolver and Bdf2ShootingStepper (SE(3))");
  const int N = options.segments;
  layout_.segments = N;
  base_quat_ = lie::RotationToQuat(base.R);
  // A pinned base holds the twist about the line. A held line need not leave its base along
  // the base frame's z (a riser from the sea bed written in a y-up world leaves across it), and
  // the twist measured from that frame would then hold the line's bending about that z too:
  // the twist's reference is the base frame turned by the least rotation onto the chord (as on
  // the SE(3) path, run/run_statics.cpp).
  if (options_.TipHeld() && options_.base_end == EndCondition::kPinned && options_.base_twist_held)
    base_quat_ = lie::RotationToQuat(lie::SO3TurnedOnto(base.R, options_.tip_position_W - base.p));

  // Segments (stretch and shear, translational and rotary inertia) sampled at their midpoints;
  // each lumps half its mass and length on either vertex.
  segment_.resize(N);
  rotation_.resize(N);
  inv_inertia_.resize(N);
  mass_.assign(N + 1, 0.0);
  vertex_weight_.assign(N + 1, 0.0);
  std::vector<double> displaced(N + 1, 0.0);  // volume a vertex displaces in a fluid, m³
  for (int i = 0; i < N; ++i) {
    const double ds = s_[i + 1] - s_[i], mid = 0.5 * (s_[i] + s_[i + 1]);
    const SectionProperties sp = PrincipalAxesSectionAt(rod, mid, actuation);
    kernels::SegmentConstants& c = segment_[i];
    c.ds = ds;
    c.stiffness = Block(sp.stiffness, 3, 3);
    c.damping = Block(sp.damping, 3, 3);
    c.rest = SectionLaw::At(rod, mid, actuation).rest_strain.tail<3>();  // with chambers
    rotation_[i].inertia = sp.mass.diagonal().head<3>() * ds;
    inv_inertia_[i] = rotation_[i].inertia.cwiseInverse();
    const double half_mass = 0.5 * sp.mass(3, 3) * ds;
    mass_[i] += half_mass;
    mass_[i + 1] += half_mass;
    vertex_weight_[i] += 0.5 * ds;
    vertex_weight_[i + 1] += 0.5 * ds;
    const double half_volume = 0.125 * M_PI * sp.outer_diameter * sp.outer_diameter * ds;
    displaced[i] += half_volume;
    displaced[i + 1] += half_volume;
  }
  // The diameter of the cylinder of the vertex's dual length that displaces its volume.
  vertex_diameter_.resize(N + 1);
  for (int n = 0; n <= N; ++n)
    vertex_diameter_[n] = std::sqrt(4.0 * displaced[n] / (M_PI * vertex_weight_[n]));

  SetUpBendElements(rod, actuation);

  fixed_.assign(size(), 0);
  if (options.base_end != EndCondition::kFree)
    for (int k = 0; k < 3; ++k) fixed_[L::X(0) + k] = 1;
  if (options.TipHeld())
    for (int k = 0; k < 3; ++k) fixed_[L::X(N) + k] = 1;

  {
    const SectionProperties e = PrincipalAxesSectionAt(rod, length() * (1 - 1e-9), actuation);
    tip_compliance_ = Block(e.stiffness, 0, 0).inverse();
    tip_rest_ =
        rod.RestStrainAt(length()).head<3>() + ChamberShift(rod, length() * (1 - 1e-9), actuation);
    tip_h_ = s_[N] - s_[N - 1];
  }
  const SectionProperties s0 = PrincipalAxesSectionAt(rod, 0.0, actuation);
  const double EI = s0.max_bending_stiffness();
  moment_scale_ = EI / length();
  force_scale_ = EI / (length() * length());
  set_loads(StaticLoads{});  // unloaded until the caller sets loads
}

QuatFdModel::Chord QuatFdModel::VertexChord(const Eigen::Ref<const Eigen::VectorXd>& q,
                                            int n) const {
  Chord c;
  c.a = std::max(n - 1, 0);
  c.b = std::min(n + 1, layout_.segments);
  const Vec3 d = q.segment<3>(L::X(c.b)) - q.segment<3>(L::X(c.a));
  c.length = d.norm();
  c.t = d / c.length;
  return c;
}

Vec3 QuatFdModel::VertexDirection(const Eigen::Ref<const Eigen::VectorXd>& q, int n) const {
  return VertexChord(q, n).t;
}

template <typename T>
kernels::V4<T> QuatFdModel::TipQuaternion(const kernels::V4<T>& p_last) const {
  // The free end's moment condition gives K(L) = K*(L) + C_K⁻¹ m_B; the frame at s = L is that of
  // p_{N−1/2} turned by K(L) Δs/2 (second order), with [1, θ/2] for the rotation θ (R(p) only
  // needs the direction of p). A world moment is taken to the body with R(p_{N−1/2}).
  V3<T> m = tip_wrench_.follower_B.head<3>().cast<T>();
  if (!tip_wrench_.dead_W.head<3>().isZero(0.0))
    m += kernels::ToBody<T>(p_last, V3<T>(tip_wrench_.dead_W.head<3>().cast<T>()));
  const V3<T> k = tip_rest_.cast<T>() + tip_compliance_.cast<T>() * m;
  const V3<T> half = T(0.5 * tip_h_) * k * T(0.5);
  return lie::QuatMultiply<T>(p_last, kernels::V4<T>(T(1), half[0], half[1], half[2]));
}

template <typename T>
void QuatFdModel::TipLoads(const kernels::V4<T>& p_last, kernels::V3<T>* force_W,
                           kernels::V3<T>* torque_B) const {
  const Vec3 force_dead = tip_wrench_.dead_W.tail<3>(),
             force_follower = tip_wrench_.follower_B.tail<3>();
  const Vec3 moment_dead = tip_wrench_.dead_W.head<3>(),
             moment_follower = tip_wrench_.follower_B.head<3>();
  // Force on x_N: the dead part as given, the follower part turned by the tip frame.
  *force_W = force_dead.cast<T>();
  if (!force_follower.isZero(0.0))
    *force_W += kernels::ToWorld<T>(TipQuaternion<T>(p_last), V3<T>(force_follower.cast<T>()));
  // Body torque on the last segment: a dead moment rotated into its frame, a follower (tip-frame)
  // moment rotated from the tip frame into it.
  *torque_B = kernels::ToBody<T>(p_last, V3<T>(moment_dead.cast<T>()));
  if (!moment_follower.isZero(0.0)) {
    const kernels::V4<T> pt = TipQuaternion<T>(p_last);
    *torque_B +=
        kernels::ToBody<T>(p_last, kernels::ToWorld<T>(pt, V3<T>(moment_follower.cast<T>())));
  }
}

// The state and energy read-outs (quatfd_model_state.cpp) use the double versions.
template kernels::V4<double> QuatFdModel::TipQuaternion<double>(const kernels::V4<double>&) const;
template void QuatFdModel::TipLoads<double>(const kernels::V4<double>&, kernels::V3<double>*,
                                            kernels::V3<double>*) const;
// The Jacobian path (quatfd_model_jacobian.cpp) differentiates the tip loads with Jets.
template void QuatFdModel::TipLoads<ceres::Jet<double, 4>>(
    const kernels::V4<ceres::Jet<double, 4>>&, kernels::V3<ceres::Jet<double, 4>>*,
    kernels::V3<ceres::Jet<double, 4>>*) const;

void QuatFdModel::TipLoadsJacobian(const Vec4& p_last, Vec3* force_W, Vec3* torque_B,
                                   Eigen::Matrix<double, 3, 4>* force_p,
                                   Eigen::Matrix<double, 3, 4>* torque_p) const {
  // With e = [1, h k/4] the tip turn (TipQuaternion: p_t = p ⊗ e), R(p_t) = R(p) R(e):
  //   world force: constant;  body force f = R(p) R(e) F:
  //     ∂f/∂p = −R(p) [R(e) F]× G(p) − R(p) R(e) [F]× G(e) ∂e/∂p;
  //   world moment τ = R(p)ᵀ m: ∂τ/∂p = [τ]× G(p), and it turns the tip (k depends on m_B):
  //     ∂e⃗/∂p = (h/4) C_K⁻¹ [m_B]× G(p);
  //   body moment τ = R(e) m with e constant: ∂τ/∂p = 0.
  TipLoads<double>(p_last, force_W, torque_B);
  force_p->setZero();
  torque_p->setZero();
  const Vec3 moment_dead = tip_wrench_.dead_W.head<3>();
  const Vec3 F = tip_wrench_.follower_B.tail<3>();
  const bool dead_moment = !moment_dead.isZero(0.0);
  const kernels::M34 Gp = (2.0 / p_last.squaredNorm()) * kernels::ImConjMulMatrix(p_last);
  const Vec3 moment_dead_B = kernels::ToBody<double>(p_last, moment_dead);
  if (dead_moment) *torque_p = kernels::Skew(moment_dead_B) * Gp;
  if (F.isZero(0.0)) return;
  const Vec3 m = moment_dead_B + tip_wrench_.follower_B.head<3>();
  const Vec3 half = 0.25 * tip_h_ * (tip_rest_ + tip_compliance_ * m);
  const Vec4 e(1.0, half[0], half[1], half[2]);
  const Mat3 Rp = kernels::RotationMatrix(p_last), Re = kernels::RotationMatrix(e);
  *force_p = -Rp * kernels::Skew(Re * F) * Gp;
  if (dead_moment) {
    const kernels::M34 Ge = (2.0 / e.squaredNorm()) * kernels::ImConjMulMatrix(e);
    const kernels::M34 half_p = 0.25 * tip_h_ * tip_compliance_ * kernels::Skew(moment_dead_B) * Gp;
    *force_p -= Rp * Re * kernels::Skew(F) * Ge.rightCols<3>() * half_p;
  }
}

void QuatFdModel::AddExternalLoads(const Vec3& tip_force_W, const Vec3& tip_torque_B,
                                   Eigen::Ref<Eigen::VectorXd> a) const {
  const int N = layout_.segments;
  for (int n = 0; n <= N; ++n) a.segment<3>(L::X(n)) += vertex_force_W_[n];
  a.segment<3>(L::X(N)) += tip_force_W;
  a.segment<3>(L::P(N - 1) + 1) += tip_torque_B;
}

void QuatFdModel::AddMotionLoads(const Eigen::Ref<const Eigen::VectorXd>& q,
                                 const Eigen::Ref<const Eigen::VectorXd>& v,
                                 Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                 BandedMatrix* dfdv) const {
  const int N = layout_.segments;
  MotionJacobian J;
  for (int n = 0; n <= N; ++n) {
    // The centreline direction at vertex n: the chord between its neighbours.
    const Chord chord = VertexChord(q, n);
    const int a_n = chord.a, b_n = chord.b;
    const double length = chord.length;
    const Vec3& t = chord.t;
    const SectionMotion motion{q.segment<3>(L::X(n)), t, v.segment<3>(L::X(n))};
    const int r = L::X(n);
    a.segment<3>(r) +=
        TotalMotionForce_W(motion_loads(), VertexSite(n), motion, dfdq ? &J : nullptr);
    if (!dfdq) continue;
    const Mat3 f_xb = J.tangent * (Mat3::Identity() - t * t.transpose()) / length;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        (*dfdq)(r + i, r + j) += J.position(i, j);
        (*dfdq)(r + i, L::X(b_n) + j) += f_xb(i, j);
        (*dfdq)(r + i, L::X(a_n) + j) -= f_xb(i, j);
        (*dfdv)(r + i, r + j) += J.velocity(i, j);
      }
    }
  }
}

void QuatFdModel::DivideVertexRowsByMass(const Eigen::Ref<const Eigen::VectorXd>& q,
                                         Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                         BandedMatrix* dfdv) const {
  for (int n = 0; n <= layout_.segments; ++n) {
    const int r = L::X(n);
    if (!fixed_[r] && vertex_added_mass(n) > 0) {
      DivideVertexRowsByMassMatrix(q, n, a, dfdq, dfdv);
      continue;
    }
    const double inv_m = fixed_[r] ? 0.0 : 1.0 / mass_[n];
    a.segment<3>(r) *= inv_m;
    if (!dfdq) continue;
    for (int i = r; i < r + 3; ++i) {
      const int c0 = std::max(0, i - L::kBandwidth), c1 = std::min(size() - 1, i + L::kBandwidth);
      for (int c = c0; c <= c1; ++c) {
        (*dfdq)(i, c) *= inv_m;
        (*dfdv)(i, c) *= inv_m;
      }
    }
  }
  // A moving tip anchor: its vertex driven as the oscillator ẍ = −ω² (x − x̄ − A) (QuatFdOptions).
  const double w = options_.tip_motion_angular_frequency;
  if (!options_.TipHeld() || w == 0.0) return;
  const int r = L::X(layout_.segments);
  a.segment<3>(r) =
      -w * w * (q.segment<3>(r) - options_.tip_position_W - options_.tip_motion_amplitude);
  if (dfdq)
    for (int i = r; i < r + 3; ++i) (*dfdq)(i, i) = -w * w;
}

void QuatFdModel::DivideVertexRowsByMassMatrix(const Eigen::Ref<const Eigen::VectorXd>& q, int n,
                                               Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                               BandedMatrix* dfdv) const {
  // M = m I + m_a (I − t tᵀ) has M⁻¹ = α I + β t tᵀ with α = 1/(m + m_a), β = 1/m − α.
  const int r = L::X(n);
  const Chord chord = VertexChord(q, n);
  const Vec3& t = chord.t;
  const double alpha = 1.0 / (mass_[n] + added_mass_[n]), beta = 1.0 / mass_[n] - alpha;
  const Mat3 inv_M = alpha * Mat3::Identity() + beta * t * t.transpose();
  const Vec3 Q = a.segment<3>(r);
  a.segment<3>(r) = inv_M * Q;
  if (!dfdq) return;
  // The rows of vertex n reach from x_{n−1} to x_{n+1} (columns r − 7 … r + 9); columns r − 8 …
  // r + 10 lie in the band of all three rows. Their derivatives turn with M⁻¹ as the forces do.
  const int c0 = std::max(0, r - 8), c1 = std::min(size() - 1, r + 10);
  for (BandedMatrix* J : {dfdq, dfdv}) {
    for (int c = c0; c <= c1; ++c) {
      const Vec3 column((*J)(r, c), (*J)(r + 1, c), (*J)(r + 2, c));
      const Vec3 turned = inv_M * column;
      for (int i = 0; i < 3; ++i) (*J)(r + i, c) = turned(i);
    }
  }
  // ∂(M⁻¹ Q)/∂t = β (t Qᵀ + (tᵀQ) I), and ∂t/∂x_b = (I − t tᵀ)/|d| = −∂t/∂x_a.
  const Mat3 dx_b = beta * (t * Q.transpose() + t.dot(Q) * Mat3::Identity()) *
                    (Mat3::Identity() - t * t.transpose()) / chord.length;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      (*dfdq)(r + i, L::X(chord.b) + j) += dx_b(i, j);
      (*dfdq)(r + i, L::X(chord.a) + j) -= dx_b(i, j);
    }
}

void QuatFdModel::EvaluateValue(const Eigen::Ref<const Eigen::VectorXd>& q,
                                const Eigen::Ref<const Eigen::VectorXd>& v, double alpha,
                                double beta, Eigen::Ref<Eigen::VectorXd> a,
                                bool forces_only) const {
  // Evaluate's two phases in one pass over the segments, the sums in the same order: segment ν's
  // forces, then bending element ν (between segments ν − 1 and ν), after which segment ν − 1's
  // torque is complete (its own, bending elements ν − 1 and ν) and its quaternion acceleration
  // follows. Each segment's frame (1/|p|², R(p), ω; Frame above) is formed once and shared by
  // its segment, both bending elements and the acceleration.
  const int N = layout_.segments;
  a.setZero();
  const auto accelerate = [&](int i, const Vec4& p, const Vec4& pd, const SegmentFrame& f) {
    const int pp = L::P(i);
    const Vec3 tau = a.segment<3>(pp + 1);
    a.segment<4>(pp) = QuaternionAccelerationFrame(rotation_[i].inertia, inv_inertia_[i], alpha,
                                                   beta, p, pd, f, tau);
  };
  Vec4 p_prev = Vec4::Zero(), pd_prev = Vec4::Zero();
  SegmentFrame f_prev{};
  for (int i = 0; i < N; ++i) {
    const int xa = L::X(i), xb = L::X(i + 1), pp = L::P(i);
    const Vec4 p = Value<4>(q, pp), pd = Value<4>(v, pp);
    const SegmentFrame f = Frame(p, pd);
    {
      Vec3 fa, tau;
      SegmentForcesFrame(segment_[i], Value<3>(q, xb) - Value<3>(q, xa),
                         Value<3>(v, xb) - Value<3>(v, xa), f, &fa, &tau);
      a.segment<3>(xa) += fa;
      a.segment<3>(xb) -= fa;
      a.segment<3>(pp + 1) += tau;
    }
    if (bend_active_[i]) {
      const bool clamp = i == 0;
      Vec3 ta, tb;
      if (clamp) {
        kernels::BendTorquesOmega<double>(bend_[i], base_quat_, p, Vec3::Zero(), f.omega, &ta, &tb);
      } else {
        kernels::BendTorquesOmega<double>(bend_[i], p_prev, p, f_prev.omega, f.omega, &ta, &tb);
        a.segment<3>(L::P(i - 1) + 1) += ta;
      }
      a.segment<3>(pp + 1) += tb;
    }
    if (i > 0 && !forces_only) accelerate(i - 1, p_prev, pd_prev, f_prev);
    p_prev = p;
    pd_prev = pd;
    f_prev = f;
  }
  if (bend_active_[N]) {  // the tip's clamp
    Vec3 ta, tb;
    kernels::BendTorquesOmega<double>(bend_[N], p_prev, tip_quat_, f_prev.omega, Vec3::Zero(), &ta,
                                      &tb);
    a.segment<3>(L::P(N - 1) + 1) += ta;
  }
  Vec3 tip_force_W, tip_torque_B;
  TipLoads<double>(p_prev, &tip_force_W, &tip_torque_B);
  AddExternalLoads(tip_force_W, tip_torque_B, a);
  if (motion_loads_) AddMotionLoads(q, v, a, nullptr, nullptr);
  if (forces_only) {
    ZeroFixedRows(a);
    return;
  }
  DivideVertexRowsByMass(q, a, nullptr, nullptr);
  accelerate(N - 1, p_prev, pd_prev, f_prev);
}

void QuatFdModel::Acceleration(const Eigen::Ref<const Eigen::VectorXd>& q,
                               const Eigen::Ref<const Eigen::VectorXd>& v,
                               Eigen::Ref<Eigen::VectorXd> a) const {
  EvaluateValue(q, v, options_.baumgarte_alpha, options_.baumgarte_beta, a, false);
}

void QuatFdModel::Acceleration(const Eigen::Ref<const Eigen::VectorXd>& q,
                               const Eigen::Ref<const Eigen::VectorXd>& v, double alpha,
                               double beta, Eigen::Ref<Eigen::VectorXd> a) const {
  EvaluateValue(q, v, alpha, beta, a, false);
}

void QuatFdModel::Jacobian(const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v, BandedMatrix* dfdq,
                           BandedMatrix* dfdv, Eigen::VectorXd* a) const {
  Jacobian(q, v, options_.baumgarte_alpha, options_.baumgarte_beta, dfdq, dfdv, a);
}

void QuatFdModel::Forces(const Eigen::Ref<const Eigen::VectorXd>& q,
                         const Eigen::Ref<const Eigen::VectorXd>& v,
                         Eigen::Ref<Eigen::VectorXd> forces) const {
  EvaluateValue(q, v, 0.0, 0.0, forces, true);
}

}  // namespace cosserat::quatfd
