#pragma once
/// \file
/// Unit quaternions as plain Vec4 q = [w, x, y, z] (scalar first, Hamilton product, ij = k).
/// q and −q are the same rotation. QuatToRotation(q) is the matrix R with QuatRotate(q, x) = R x,
/// i.e. the same R as SO3Exp(θ a) for q = [cos(θ/2), sin(θ/2) a]. Used by the quaternion
/// finite-difference model (Lang & Linn 2009). Note that Eigen::Quaterniond stores [x, y, z, w] in
/// memory. QuatToRotation, RotationToQuat and the axis-angle maps are compiled once, in
/// src/lie/quaternion.cpp; the short ones (multiply, conjugate, normalise, rotate) stay inline.

#include <Eigen/Geometry>
#include <cmath>

#include "cosserat/lie/so3.hpp"

namespace cosserat::lie {

/// Hamilton product a ⊗ b = [a_w b_w − a_v·b_v; a_w b_v + b_w a_v + a_v × b_v], written out by
/// component. Templated on the scalar (the quaternion finite-difference kernels use it with
/// ceres::Jet). For unit quaternions, QuatToRotation(a ⊗ b) = QuatToRotation(a) QuatToRotation(b).
template <typename T>
inline Eigen::Matrix<T, 4, 1> QuatMultiply(const Eigen::Matrix<T, 4, 1>& a,
                                           const Eigen::Matrix<T, 4, 1>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
inline Vec4 QuatMultiply(const Vec4& a, const Vec4& b) { return QuatMultiply<double>(a, b); }

/// Conjugate [w, −x, −y, −z]; the inverse of a unit quaternion.
inline Vec4 QuatConjugate(const Vec4& q) { return Vec4(q[0], -q[1], -q[2], -q[3]); }

/// q / |q|. The zero quaternion has no direction and yields NaN.
inline Vec4 QuatNormalized(const Vec4& q) { return q / q.norm(); }

/// Rotation matrix of a unit quaternion: R = (w² − |u|²) I + 2 u u^T + 2 w hat(u), u = [x, y, z].
/// Not normalised internally: a non-unit q gives |q|² times a rotation.
Mat3 QuatToRotation(const Vec4& q);

/// Quaternion of a rotation matrix by Shepperd's method: the largest of 4w², 4x², 4y², 4z² is
/// taken from the diagonal, the others from off-diagonal sums over it, so no division is by less
/// than 1/2. Returns a unit quaternion with w ≥ 0 (at θ = π, where w = 0, the sign is arbitrary).
Vec4 RotationToQuat(const Mat3& R);

/// Unit quaternion of the rotation vector w (rad): [cos(θ/2), sin(θ/2)/θ · w] = exp([0, w/2]).
/// Exact at w = 0 (Taylor branch for small θ).
Vec4 QuatFromAxisAngle(const Vec3& w);

/// Rotation vector w (rad, |w| ≤ π) of a quaternion: inverse of QuatFromAxisAngle up to the sign
/// of q (q is first flipped to w ≥ 0). Depends only on the direction of q, so a slightly non-unit
/// q is fine.
Vec3 QuatToAxisAngle(const Vec4& q_in);

/// Rotates x by the unit quaternion q: q ⊗ [0, x] ⊗ q*, computed as
/// x + 2w (u × x) + 2 u × (u × x). Equals QuatToRotation(q) * x.
inline Vec3 QuatRotate(const Vec4& q, const Vec3& x) {
  const Vec3 u = q.tail<3>();
  const Vec3 t = 2.0 * u.cross(x);
  return x + q[0] * t + u.cross(t);
}

}  // namespace cosserat::lie
