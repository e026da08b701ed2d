#pragma once
/// \file
/// SO(3): hat, vee, exponential and logarithm, left and right Jacobians.
/// FD notes 2025, eqs. 1–2. Angles in rad; a rotation vector w = θ a has angle θ = |w| and unit
/// axis a.
///
/// Jacobian convention (Barfoot; Sola et al. "A micro Lie theory"), for small dw:
///   Exp(w + dw) ≈ Exp(J_l(w) dw) Exp(w) ≈ Exp(w) Exp(J_r(w) dw),   J_r(w) = J_l(−w) = J_l(w)^T.
/// Every closed form has a Taylor branch for θ² < kSO3Taylor2, so all functions are exact at w = 0.

#include <cmath>

#include "cosserat/lie/types.hpp"

namespace cosserat::lie {

/// Skew-symmetric matrix with hat(w) * r = w × r.
template <typename T>
inline Matrix3<T> hat(const Vector3<T>& w) {
  Matrix3<T> W;
  W << T(0), -w.z(), w.y(),  //
      w.z(), T(0), -w.x(),   //
      -w.y(), w.x(), T(0);
  return W;
}

/// Inverse of hat: the axial vector of the skew part of W.
template <typename T>
inline Vector3<T> vee(const Matrix3<T>& W) {
  return Vector3<T>(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)) * T(0.5);
}

// Every map of this file is a template on the scalar T (double, or ceres::Jet to differentiate
// through it, as in Sophus and manif), with a double overload that also takes Eigen expressions.
// hat and vee are inline; the other double overloads are compiled once, in src/lie/so3.cpp, so
// that a source which includes this header does not instantiate them all.
inline Mat3 hat(const Vec3& w) { return hat<double>(w); }
inline Vec3 vee(const Mat3& W) { return vee<double>(W); }

/// Below this θ² (rad²) the SO(3) coefficients use their Taylor series up to θ⁴. The first omitted
/// term is O(θ⁶) ≤ 1e-18 relative, far below round-off; above it the closed forms lose at most
/// O(eps) in absolute value (their cancellations are multiplied by hat(w)^k = O(θ^k)).
inline constexpr double kSO3Taylor2 = 1e-6;

namespace detail {
/// Coefficients of I, hat(w), hat(w)² shared by Exp and the Jacobians, as functions of θ = |w|:
/// a = sin θ / θ, b = (1 − cos θ) / θ², c = (θ − sin θ) / θ³.
template <typename T>
struct SO3Coeffs {
  T a, b, c;
};
template <typename T>
inline SO3Coeffs<T> so3_coeffs(const T& theta2) {
  using std::sin;
  using std::sqrt;
  if (theta2 < kSO3Taylor2) {
    return {T(1.0) - theta2 / 6.0 * (T(1.0) - theta2 / 20.0),   //
            T(0.5) - theta2 / 24.0 * (T(1.0) - theta2 / 30.0),  //
            T(1.0 / 6.0) - theta2 / 120.0 * (T(1.0) - theta2 / 42.0)};
  }
  const T theta = sqrt(theta2);
  const T s = sin(theta), sh = sin(0.5 * theta);
  return {s / theta, 2.0 * sh * sh / theta2, (theta - s) / (theta2 * theta)};
}
/// Coefficient of hat(w)² in J_l^{-1}: d = (1 − (θ/2) cot(θ/2)) / θ², finite up to θ < 2π.
template <typename T>
inline T so3_inv_coeff(const T& theta2) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta2 < kSO3Taylor2) return T(1.0 / 12.0) + theta2 / 720.0 * (T(1.0) + theta2 / 42.0);
  const T half = 0.5 * sqrt(theta2);
  return (T(1.0) - half * cos(half) / sin(half)) / theta2;
}
}  // namespace detail

/// Exponential map (Rodrigues): rotation R = exp(hat(w)) for rotation vector w (rad).
/// R maps vectors of the rotated frame into the reference frame. SO3Exp(0) is exactly I.
template <typename T>
inline Matrix3<T> SO3Exp(const Vector3<T>& w) {
  const auto k = detail::so3_coeffs<T>(w.squaredNorm());
  const Matrix3<T> W = hat<T>(w);
  return Matrix3<T>::Identity() + k.a * W + k.b * W * W;
}
Mat3 SO3Exp(const Vec3& w);

/// Logarithm map: rotation vector w (rad) with SO3Exp(w) = R and |w| ∈ [0, π].
/// At θ = π both ±w are valid; the sign is then arbitrary. For θ < π/2 the axis comes from the
/// skew part, sin θ · a = vee(R); for θ ≥ π/2 it comes from the symmetric part
/// (R + R^T)/2 − cos θ I = (1 − cos θ) a a^T, whose largest column is well conditioned up to θ = π.
template <typename T>
inline Vector3<T> SO3Log(const Matrix3<T>& R) {
  using std::atan2;
  using std::sin;
  using std::sqrt;
  const Vector3<T> sin_axis = vee<T>(R);  // sin θ · a
  const T c = 0.5 * (R.trace() - 1.0);    // cos θ
  const T s2 = sin_axis.squaredNorm();    // sin² θ
  if (c > 0.0 && s2 < kSO3Taylor2) {
    // θ / sin θ = 1 + sin²θ/6 + O(sin⁴θ), without the norm's square root, whose derivative at
    // zero is infinite (automatic differentiation at the identity would give NaN).
    return (T(1.0) + s2 / 6.0 * (T(1.0) + 0.45 * s2)) * sin_axis;
  }
  const T theta = atan2(sqrt(s2), c);
  const T theta2 = theta * theta;
  if (c > 0.0) {
    // θ / sin θ, with its Taylor series for small θ.
    const T f = theta2 < kSO3Taylor2 ? T(1.0) + theta2 / 6.0 * (T(1.0) + 7.0 * theta2 / 60.0)
                                     : T(theta / sin(theta));
    return f * sin_axis;
  }
  const Matrix3<T> S = 0.5 * (R + R.transpose()) - c * Matrix3<T>::Identity();
  Eigen::Index i = 0;
  S.diagonal().maxCoeff(&i);
  Vector3<T> axis = S.col(i).normalized();
  if (axis.dot(sin_axis) < 0.0) axis = -axis;
  return theta * axis;
}
Vec3 SO3Log(const Mat3& R);

/// Left Jacobian of SO3Exp: J_l(w) = I + b hat(w) + c hat(w)² (see detail::SO3Coeffs).
/// Exp(w + dw) ≈ Exp(J_l(w) dw) Exp(w): maps a change of w to a rotation increment in the
/// reference (left) frame. Also the matrix with p = J_l(w) v in SE3Exp.
template <typename T>
inline Matrix3<T> SO3LeftJacobian(const Vector3<T>& w) {
  const auto k = detail::so3_coeffs<T>(w.squaredNorm());
  const Matrix3<T> W = hat<T>(w);
  return Matrix3<T>::Identity() + k.b * W + k.c * W * W;
}
Mat3 SO3LeftJacobian(const Vec3& w);

/// Right Jacobian of SO3Exp: J_r(w) = J_l(−w) = J_l(w)^T; Exp(w + dw) ≈ Exp(w) Exp(J_r(w) dw).
template <typename T>
inline Matrix3<T> SO3RightJacobian(const Vector3<T>& w) {
  return SO3LeftJacobian<T>(-w);
}
Mat3 SO3RightJacobian(const Vec3& w);

/// Inverse of the left Jacobian: J_l^{-1}(w) = I − hat(w)/2 + d hat(w)², valid for |w| < 2π.
/// J_l^{-1}(Log R) is the derivative of Log(Exp(δ) R) with respect to δ at δ = 0.
template <typename T>
inline Matrix3<T> SO3LeftJacobianInverse(const Vector3<T>& w) {
  const Matrix3<T> W = hat<T>(w);
  return Matrix3<T>::Identity() - 0.5 * W + detail::so3_inv_coeff<T>(w.squaredNorm()) * W * W;
}
Mat3 SO3LeftJacobianInverse(const Vec3& w);

/// Inverse of the right Jacobian: J_r^{-1}(w) = J_l^{-1}(−w), valid for |w| < 2π.
/// J_r^{-1}(Log R) is the derivative of Log(R Exp(δ)) with respect to δ at δ = 0.
template <typename T>
inline Matrix3<T> SO3RightJacobianInverse(const Vector3<T>& w) {
  return SO3LeftJacobianInverse<T>(-w);
}
Mat3 SO3RightJacobianInverse(const Vec3& w);

/// R turned by the least rotation that takes its third column onto the direction d (any length
/// > 0): a frame's axis laid along d with no turn about it (half a turn about the first column
/// when d points the other way). R itself when d is zero.
Mat3 SO3TurnedOnto(const Mat3& R, const Vec3& d);

}  // namespace cosserat::lie
