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
/// As in so3.hpp, the double overloads of the maps are compiled once, in src/lie/se3.cpp.

#include <cmath>

#include "cosserat/lie/so3.hpp"

namespace cosserat::lie {

/// Rigid motion g = (R, p) with matrix form [[R, p], [0, 1]]. For a body pose: R = R_WB (maps body
/// vectors to world), p = p_W (origin of B in world, m). Templated on the scalar like the rest of
/// the lie layer; SE3 is the double pose every solver uses.
template <typename T>
struct SE3T {
  Matrix3<T> R = Matrix3<T>::Identity();
  Vector3<T> p = Vector3<T>::Zero();
};
using SE3 = SE3T<double>;

template <typename T>
using Matrix4 = Eigen::Matrix<T, 4, 4>;

/// Adjoint of g on twists [ω; v]: Ad(g) = [[R, 0], [hat(p) R, R]], so that
/// hat6(Ad(g) ξ) = g hat6(ξ) g^{-1}. Maps a twist expressed in frame B to frame W when g = g_WB.
template <typename T>
inline Matrix6<T> Ad(const SE3T<T>& g) {
  Matrix6<T> A;
  A << g.R, Matrix3<T>::Zero(), hat<T>(g.p) * g.R, g.R;
  return A;
}

/// Inverse pose (R^T, −R^T p). Optional J_ginv_g = −Ad(g).
template <typename T>
inline SE3T<T> Inverse(const SE3T<T>& g, Matrix6<T>* J_ginv_g = nullptr) {
  if (J_ginv_g) *J_ginv_g = -Ad(g);
  return {g.R.transpose(), -(g.R.transpose() * g.p)};
}

/// Composition a ∘ b = (R_a R_b, R_a p_b + p_a), e.g. g_WC = Compose(g_WB, g_BC).
/// Optional J_ab_a = Ad(b^{-1}) and J_ab_b = I.
template <typename T>
inline SE3T<T> Compose(const SE3T<T>& a, const SE3T<T>& b, Matrix6<T>* J_ab_a = nullptr,
                       Matrix6<T>* J_ab_b = nullptr) {
  if (J_ab_a) *J_ab_a = Ad(Inverse(b));
  if (J_ab_b) J_ab_b->setIdentity();
  return {a.R * b.R, a.R * b.p + a.p};
}

/// 4×4 homogeneous matrix [[R, p], [0, 1]].
template <typename T>
inline Matrix4<T> ToMatrix(const SE3T<T>& g) {
  Matrix4<T> M = Matrix4<T>::Identity();
  M.template topLeftCorner<3, 3>() = g.R;
  M.template topRightCorner<3, 1>() = g.p;
  return M;
}

/// Pose from a 4×4 homogeneous matrix; the last row is ignored, R is not re-orthonormalised.
template <typename T>
inline SE3T<T> FromMatrix(const Matrix4<T>& M) {
  return {M.template topLeftCorner<3, 3>(), M.template topRightCorner<3, 1>()};
}

/// Action on a point: y = R x + p (x in the body frame B, y in W when g = g_WB; m).
/// Optional J_y_g = [−R hat(x), R] (3×6, columns [ω; v]) and J_y_x = R.
template <typename T>
inline Vector3<T> Act(const SE3T<T>& g, const Vector3<T>& x,
                      Eigen::Matrix<T, 3, 6>* J_y_g = nullptr, Matrix3<T>* J_y_x = nullptr) {
  if (J_y_g) *J_y_g << -g.R * hat<T>(x), g.R;
  if (J_y_x) *J_y_x = g.R;
  return g.R * x + g.p;
}

/// se(3) matrix of the twist ξ = [ω; v]: [[hat(ω), v], [0, 0]] (FD notes 2025, eq. 4).
template <typename T>
inline Matrix4<T> hat6(const Vector6<T>& xi) {
  Matrix4<T> X = Matrix4<T>::Zero();
  X.template topLeftCorner<3, 3>() = hat<T>(xi.template head<3>());
  X.template topRightCorner<3, 1>() = xi.template tail<3>();
  return X;
}
Mat4 hat6(const Vec6& xi);

/// Inverse of hat6: [vee(top-left 3×3); top-right column].
template <typename T>
inline Vector6<T> vee6(const Matrix4<T>& X) {
  Vector6<T> xi;
  xi << vee<T>(X.template topLeftCorner<3, 3>()), X.template topRightCorner<3, 1>();
  return xi;
}
Vec6 vee6(const Mat4& X);

/// Exponential map: Exp(ξ) = exp(hat6(ξ)) = (SO3Exp(ω), J_l(ω) v) for ξ = [ω; v].
/// E.g. the pose reached from the identity by a constant strain ξ over unit arc length.
template <typename T>
inline SE3T<T> SE3Exp(const Vector6<T>& xi) {
  const Vector3<T> w = xi.template head<3>();
  return {SO3Exp<T>(w), SO3LeftJacobian<T>(w) * xi.template tail<3>()};
}
SE3 SE3Exp(const Vec6& xi);

/// Logarithm map: ξ = [ω; v] with ω = SO3Log(R), |ω| ≤ π, and v = J_l(ω)^{-1} p.
template <typename T>
inline Vector6<T> SE3Log(const SE3T<T>& g) {
  const Vector3<T> w = SO3Log<T>(g.R);
  Vector6<T> xi;
  xi << w, SO3LeftJacobianInverse<T>(w) * g.p;
  return xi;
}

/// Adjoint of the Lie algebra on twists: ad(ξ) = [[hat(ω), 0], [hat(v), hat(ω)]], so that
/// ad(x) y = [x, y] = vee6(hat6(x) hat6(y) − hat6(y) hat6(x)). FD notes 2025, eq. 5, [ω; v] order.
template <typename T>
inline Matrix6<T> ad(const Vector6<T>& xi) {
  const Matrix3<T> W = hat<T>(xi.template head<3>());
  Matrix6<T> A;
  A << W, Matrix3<T>::Zero(), hat<T>(xi.template tail<3>()), W;
  return A;
}
Mat6 ad(const Vec6& xi);

/// Coadjoint on wrenches μ = [m; n]: coad(ξ) = ad(ξ)^T = [[−hat(ω), −hat(v)], [0, −hat(ω)]],
/// defined by <coad(ξ) μ, η> = <μ, ad(ξ) η> for every twist η. Explicitly
/// coad(ξ) [m; n] = −[ω × m + v × n; ω × n].
/// FD notes 2025, eq. 6, writes ad* = [[−Ω̂, 0], [−v̂, −Ω̂]], which is the same operator in the
/// opposite block ordering ([v; ω], wrench [n; m]); this library uses [ω; v] and [m; n] throughout.
/// With this definition their eq. 16 reads Λ' = … + coad(E) Λ − F_ext unchanged.
template <typename T>
inline Matrix6<T> coad(const Vector6<T>& xi) {
  const Matrix3<T> Wt = -hat<T>(xi.template head<3>());
  Matrix6<T> A;
  A << Wt, -hat<T>(xi.template tail<3>()), Matrix3<T>::Zero(), Wt;
  return A;
}
Mat6 coad(const Vec6& xi);

/// Below this θ² (rad²) the Q block uses Taylor series up to θ⁶ (first omitted term below
/// 3e-17 there). Above it the closed forms have cancellations of O(eps/θ) in the terms of Q, so
/// the switch sits later than for SO(3): at θ = 0.1 both branches are within ~1e-15 |v| of the
/// exact Q (checked against a long-double series).
inline constexpr double kSE3Taylor2 = 1e-2;

namespace detail {
/// Lower-left block of the SE(3) left Jacobian for ξ = [ω; v] (Barfoot's Q(ρ = v, φ = ω)):
/// Q = V/2 + c1 (WV + VW + WVW) + c2 (W²V + VW² − 3 WVW) + c3 (WVW² + W²VW), W = hat(ω), V =
/// hat(v).
template <typename T>
inline Matrix3<T> se3_Q(const Vector3<T>& w, const Vector3<T>& v) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T t2 = w.squaredNorm();
  T c1, c2, c3;
  if (t2 < kSE3Taylor2) {
    c1 = 1.0 / 6.0 - t2 / 120.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0));
    c2 = 1.0 / 24.0 - t2 / 720.0 * (1.0 - t2 / 56.0 * (1.0 - t2 / 90.0));
    c3 = 1.0 / 120.0 - t2 / 2520.0 * (1.0 - t2 / 48.0 * (1.0 - 2.0 * t2 / 165.0));
  } else {
    const T t = sqrt(t2), s = sin(t), c = cos(t), sh2 = 2.0 * sin(0.5 * t);
    c1 = (t - s) / (t2 * t);                                 // (θ − sin θ) / θ³
    c2 = (t - sh2) * (t + sh2) / (2.0 * t2 * t2);            // (θ² + 2 cos θ − 2) / (2 θ⁴)
    c3 = (2.0 * t - 3.0 * s + t * c) / (2.0 * t2 * t2 * t);  // (2θ − 3 sin θ + θ cos θ) / (2 θ⁵)
  }
  const Matrix3<T> W = hat<T>(w), V = hat<T>(v);
  const Matrix3<T> WV = W * V, VW = V * W, WVW = WV * W;
  return 0.5 * V + c1 * (WV + VW + WVW) + c2 * (W * WV + VW * W - 3.0 * WVW) +
         c3 * (WVW * W + W * WVW);
}
}  // namespace detail

/// Left Jacobian of SE3Exp: J_l(ξ) = [[J_l(ω), 0], [Q(ω, v), J_l(ω)]].
template <typename T>
inline Matrix6<T> SE3LeftJacobian(const Vector6<T>& xi) {
  const Vector3<T> w = xi.template head<3>(), v = xi.template tail<3>();
  const Matrix3<T> J = SO3LeftJacobian<T>(w);
  Matrix6<T> A;
  A << J, Matrix3<T>::Zero(), detail::se3_Q<T>(w, v), J;
  return A;
}
Mat6 SE3LeftJacobian(const Vec6& xi);

/// Right Jacobian of SE3Exp: J_r(ξ) = J_l(−ξ) = Ad(Exp(ξ))^{-1} J_l(ξ).
template <typename T>
inline Matrix6<T> SE3RightJacobian(const Vector6<T>& xi) {
  return SE3LeftJacobian<T>(-xi);
}
Mat6 SE3RightJacobian(const Vec6& xi);

/// Inverse of the left Jacobian: [[J_l(ω)^{-1}, 0], [−J_l(ω)^{-1} Q J_l(ω)^{-1}, J_l(ω)^{-1}]],
/// valid for |ω| < 2π. J_l^{-1}(Log g) = ∂ Log(Exp(δ) g) / ∂δ at δ = 0.
template <typename T>
inline Matrix6<T> SE3LeftJacobianInverse(const Vector6<T>& xi) {
  const Vector3<T> w = xi.template head<3>(), v = xi.template tail<3>();
  const Matrix3<T> Ji = SO3LeftJacobianInverse<T>(w);
  Matrix6<T> A;
  A << Ji, Matrix3<T>::Zero(), -Ji * detail::se3_Q<T>(w, v) * Ji, Ji;
  return A;
}
Mat6 SE3LeftJacobianInverse(const Vec6& xi);

/// Inverse of the right Jacobian: J_r^{-1}(ξ) = J_l^{-1}(−ξ); J_r^{-1}(Log g) = ∂ Log(g Exp(δ)) /
/// ∂δ.
template <typename T>
inline Matrix6<T> SE3RightJacobianInverse(const Vector6<T>& xi) {
  return SE3LeftJacobianInverse<T>(-xi);
}
Mat6 SE3RightJacobianInverse(const Vec6& xi);

}  // namespace cosserat::lie
