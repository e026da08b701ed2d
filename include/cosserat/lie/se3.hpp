#pragma once
/// \file
/// SE(3): poses, hat/vee, exponential and logarithm, Ad, ad, coad and the Jacobians.
/// FD notes 2025, eqs. 3–6, rewritten for the library ordering: twist ξ = [ω; v] (angular first,
/// rad and m per unit of the parameter: 1/s for velocities, 1/m and – for strains), wrench
/// μ = [m; n] (N·m and N). The notes state ξ^∨ = (Ω, v) but print their 6×6 matrices (eqs. 5–6)
/// in the [v; ω] block ordering; the matrices here are the [ω; v] versions.
///
/// Jacobian convention as in so3.hpp, for small dξ:
///   Exp(ξ + dξ) ≈ Exp(J_l(ξ) dξ) Exp(ξ) ≈ Exp(ξ) Exp(J_r(ξ) dξ).
/// The optional Jacobians J_out_in of Compose, Inverse and Act use right (body-frame)
/// perturbations of a pose, g ← g Exp(τ): J_Y_X = ∂ Log(Y(X)^{-1} Y(X Exp(τ))) / ∂τ at τ = 0.

#include <cmath>

#include "cosserat/lie/so3.hpp"

namespace cosserat::lie {

/// Rigid motion g = (R, p) with matrix form [[R, p], [0, 1]]. For a body pose: R = R_WB (maps body
/// vectors to world), p = p_W (origin of B in world, m).
struct SE3 {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
};

/// Adjoint of g on twists [ω; v]: Ad(g) = [[R, 0], [hat(p) R, R]], so that
/// hat6(Ad(g) ξ) = g hat6(ξ) g^{-1}. Maps a twist expressed in frame B to frame W when g = g_WB.
inline Mat6 Ad(const SE3& g) {
  Mat6 A;
  A << g.R, Mat3::Zero(), hat(g.p) * g.R, g.R;
  return A;
}

/// Inverse pose (R^T, −R^T p). Optional J_ginv_g = −Ad(g).
inline SE3 Inverse(const SE3& g, Mat6* J_ginv_g = nullptr) {
  if (J_ginv_g) *J_ginv_g = -Ad(g);
  return {g.R.transpose(), -(g.R.transpose() * g.p)};
}

/// Composition a ∘ b = (R_a R_b, R_a p_b + p_a), e.g. g_WC = Compose(g_WB, g_BC).
/// Optional J_ab_a = Ad(b^{-1}) and J_ab_b = I.
inline SE3 Compose(const SE3& a, const SE3& b, Mat6* J_ab_a = nullptr, Mat6* J_ab_b = nullptr) {
  if (J_ab_a) *J_ab_a = Ad(Inverse(b));
  if (J_ab_b) J_ab_b->setIdentity();
  return {a.R * b.R, a.R * b.p + a.p};
}

/// 4×4 homogeneous matrix [[R, p], [0, 1]].
inline Mat4 ToMatrix(const SE3& g) {
  Mat4 T = Mat4::Identity();
  T.topLeftCorner<3, 3>() = g.R;
  T.topRightCorner<3, 1>() = g.p;
  return T;
}

/// Pose from a 4×4 homogeneous matrix; the last row is ignored, R is not re-orthonormalised.
inline SE3 FromMatrix(const Mat4& T) { return {T.topLeftCorner<3, 3>(), T.topRightCorner<3, 1>()}; }

/// Action on a point: y = R x + p (x in the body frame B, y in W when g = g_WB; m).
/// Optional J_y_g = [−R hat(x), R] (3×6, columns [ω; v]) and J_y_x = R.
inline Vec3 Act(const SE3& g, const Vec3& x, Eigen::Matrix<double, 3, 6>* J_y_g = nullptr,
                Mat3* J_y_x = nullptr) {
  if (J_y_g) *J_y_g << -g.R * hat(x), g.R;
  if (J_y_x) *J_y_x = g.R;
  return g.R * x + g.p;
}

/// se(3) matrix of the twist ξ = [ω; v]: [[hat(ω), v], [0, 0]] (FD notes 2025, eq. 4).
inline Mat4 hat6(const Vec6& xi) {
  Mat4 X = Mat4::Zero();
  X.topLeftCorner<3, 3>() = hat<double>(xi.head<3>());
  X.topRightCorner<3, 1>() = xi.tail<3>();
  return X;
}

/// Inverse of hat6: [vee(top-left 3×3); top-right column].
inline Vec6 vee6(const Mat4& X) {
  Vec6 xi;
  xi << vee<double>(X.topLeftCorner<3, 3>()), X.topRightCorner<3, 1>();
  return xi;
}

/// Exponential map: Exp(ξ) = exp(hat6(ξ)) = (SO3Exp(ω), J_l(ω) v) for ξ = [ω; v].
/// E.g. the pose reached from the identity by a constant strain ξ over unit arc length.
inline SE3 SE3Exp(const Vec6& xi) {
  const Vec3 w = xi.head<3>();
  return {SO3Exp(w), SO3LeftJacobian(w) * xi.tail<3>()};
}

/// Logarithm map: ξ = [ω; v] with ω = SO3Log(R), |ω| ≤ π, and v = J_l(ω)^{-1} p.
inline Vec6 SE3Log(const SE3& g) {
  const Vec3 w = SO3Log(g.R);
  Vec6 xi;
  xi << w, SO3LeftJacobianInverse(w) * g.p;
  return xi;
}

/// Adjoint of the Lie algebra on twists: ad(ξ) = [[hat(ω), 0], [hat(v), hat(ω)]], so that
/// ad(x) y = [x, y] = vee6(hat6(x) hat6(y) − hat6(y) hat6(x)). FD notes 2025, eq. 5, [ω; v] order.
inline Mat6 ad(const Vec6& xi) {
  const Mat3 W = hat<double>(xi.head<3>());
  Mat6 A;
  A << W, Mat3::Zero(), hat<double>(xi.tail<3>()), W;
  return A;
}

/// Coadjoint on wrenches μ = [m; n]: coad(ξ) = ad(ξ)^T = [[−hat(ω), −hat(v)], [0, −hat(ω)]],
/// defined by <coad(ξ) μ, η> = <μ, ad(ξ) η> for every twist η. Explicitly
/// coad(ξ) [m; n] = −[ω × m + v × n; ω × n].
/// FD notes 2025, eq. 6, writes ad* = [[−Ω̂, 0], [−v̂, −Ω̂]], which is the same operator in the
/// opposite block ordering ([v; ω], wrench [n; m]); this library uses [ω; v] and [m; n] throughout.
/// With this definition their eq. 16 reads Λ' = … + coad(E) Λ − F_ext unchanged.
inline Mat6 coad(const Vec6& xi) {
  const Mat3 Wt = -hat<double>(xi.head<3>());
  Mat6 A;
  A << Wt, -hat<double>(xi.tail<3>()), Mat3::Zero(), Wt;
  return A;
}

/// Below this θ² (rad²) the Q block uses Taylor series up to θ⁶ (first omitted term below
/// 3e-17 there). Above it the closed forms have cancellations of O(eps/θ) in the terms of Q, so
/// the switch sits later than for SO(3): at θ = 0.1 both branches are within ~1e-15 |v| of the
/// exact Q (checked against a long-double series).
inline constexpr double kSE3Taylor2 = 1e-2;

namespace detail {
/// Lower-left block of the SE(3) left Jacobian for ξ = [ω; v] (Barfoot's Q(ρ = v, φ = ω)):
/// Q = V/2 + c1 (WV + VW + WVW) + c2 (W²V + VW² − 3 WVW) + c3 (WVW² + W²VW), W = hat(ω), V =
/// hat(v).
inline Mat3 se3_Q(const Vec3& w, const Vec3& v) {
  const double t2 = w.squaredNorm();
  double c1, c2, c3;
  if (t2 < kSE3Taylor2) {
    c1 = 1.0 / 6.0 - t2 / 120.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0));
    c2 = 1.0 / 24.0 - t2 / 720.0 * (1.0 - t2 / 56.0 * (1.0 - t2 / 90.0));
    c3 = 1.0 / 120.0 - t2 / 2520.0 * (1.0 - t2 / 48.0 * (1.0 - 2.0 * t2 / 165.0));
  } else {
    const double t = std::sqrt(t2), s = std::sin(t), c = std::cos(t), sh2 = 2.0 * std::sin(0.5 * t);
    c1 = (t - s) / (t2 * t);                                 // (θ − sin θ) / θ³
    c2 = (t - sh2) * (t + sh2) / (2.0 * t2 * t2);            // (θ² + 2 cos θ − 2) / (2 θ⁴)
    c3 = (2.0 * t - 3.0 * s + t * c) / (2.0 * t2 * t2 * t);  // (2θ − 3 sin θ + θ cos θ) / (2 θ⁵)
  }
  const Mat3 W = hat(w), V = hat(v);
  const Mat3 WV = W * V, VW = V * W, WVW = WV * W;
  return 0.5 * V + c1 * (WV + VW + WVW) + c2 * (W * WV + VW * W - 3.0 * WVW) +
         c3 * (WVW * W + W * WVW);
}
}  // namespace detail

/// Left Jacobian of SE3Exp: J_l(ξ) = [[J_l(ω), 0], [Q(ω, v), J_l(ω)]].
inline Mat6 SE3LeftJacobian(const Vec6& xi) {
  const Mat3 J = SO3LeftJacobian(xi.head<3>());
  Mat6 A;
  A << J, Mat3::Zero(), detail::se3_Q(xi.head<3>(), xi.tail<3>()), J;
  return A;
}

/// Right Jacobian of SE3Exp: J_r(ξ) = J_l(−ξ) = Ad(Exp(ξ))^{-1} J_l(ξ).
inline Mat6 SE3RightJacobian(const Vec6& xi) { return SE3LeftJacobian(-xi); }

/// Inverse of the left Jacobian: [[J_l(ω)^{-1}, 0], [−J_l(ω)^{-1} Q J_l(ω)^{-1}, J_l(ω)^{-1}]],
/// valid for |ω| < 2π. J_l^{-1}(Log g) = ∂ Log(Exp(δ) g) / ∂δ at δ = 0.
inline Mat6 SE3LeftJacobianInverse(const Vec6& xi) {
  const Mat3 Ji = SO3LeftJacobianInverse(xi.head<3>());
  Mat6 A;
  A << Ji, Mat3::Zero(), -Ji * detail::se3_Q(xi.head<3>(), xi.tail<3>()) * Ji, Ji;
  return A;
}

/// Inverse of the right Jacobian: J_r^{-1}(ξ) = J_l^{-1}(−ξ); J_r^{-1}(Log g) = ∂ Log(g Exp(δ)) /
/// ∂δ.
inline Mat6 SE3RightJacobianInverse(const Vec6& xi) { return SE3LeftJacobianInverse(-xi); }

}  // namespace cosserat::lie
