#pragma once
/// \file
/// Unit quaternions as plain Vec4 q = [w, x, y, z] (scalar first, Hamilton product, ij = k).
/// q and −q are the same rotation. QuatToRotation(q) is the matrix R with QuatRotate(q, x) = R x,
/// i.e. the same R as SO3Exp(θ a) for q = [cos(θ/2), sin(θ/2) a]. Used by the quaternion
/// finite-difference model (Lang & Linn 2009). Note that Eigen::Quaterniond stores [x, y, z, w] in
/// memory.

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
inline Mat3 QuatToRotation(const Vec4& q) {
  const double w = q[0];
  const Vec3 u = q.tail<3>();
  return (w * w - u.squaredNorm()) * Mat3::Identity() + 2.0 * u * u.transpose() + 2.0 * w * hat(u);
}

/// Quaternion of a rotation matrix by Shepperd's method: the largest of 4w², 4x², 4y², 4z² is
/// taken from the diagonal, the others from off-diagonal sums over it, so no division is by less
/// than 1/2. Returns a unit quaternion with w ≥ 0 (at θ = π, where w = 0, the sign is arbitrary).
inline Vec4 RotationToQuat(const Mat3& R) {
  const double tr = R.trace();
  Vec4 q;
  Eigen::Index i = 0;
  const Eigen::Vector4d d(tr, R(0, 0), R(1, 1), R(2, 2));
  d.maxCoeff(&i);
  if (i == 0) {
    const double r = std::sqrt(1.0 + tr);  // 2|w|
    q << 0.5 * r, (R(2, 1) - R(1, 2)) / (2 * r), (R(0, 2) - R(2, 0)) / (2 * r),
        (R(1, 0) - R(0, 1)) / (2 * r);
  } else if (i == 1) {
    const double r = std::sqrt(1.0 + R(0, 0) - R(1, 1) - R(2, 2));  // 2|x|
    q << (R(2, 1) - R(1, 2)) / (2 * r), 0.5 * r, (R(0, 1) + R(1, 0)) / (2 * r),
        (R(0, 2) + R(2, 0)) / (2 * r);
  } else if (i == 2) {
    const double r = std::sqrt(1.0 - R(0, 0) + R(1, 1) - R(2, 2));  // 2|y|
    q << (R(0, 2) - R(2, 0)) / (2 * r), (R(0, 1) + R(1, 0)) / (2 * r), 0.5 * r,
        (R(1, 2) + R(2, 1)) / (2 * r);
  } else {
    const double r = std::sqrt(1.0 - R(0, 0) - R(1, 1) + R(2, 2));  // 2|z|
    q << (R(1, 0) - R(0, 1)) / (2 * r), (R(0, 2) + R(2, 0)) / (2 * r),
        (R(1, 2) + R(2, 1)) / (2 * r), 0.5 * r;
  }
  if (q[0] < 0.0) q = -q;
  return q.normalized();
}

/// Unit quaternion of the rotation vector w (rad): [cos(θ/2), sin(θ/2)/θ · w] = exp([0, w/2]).
/// Exact at w = 0 (Taylor branch for small θ).
inline Vec4 QuatFromAxisAngle(const Vec3& w) {
  const double t2 = w.squaredNorm();
  const double theta = std::sqrt(t2);
  // sin(θ/2)/θ = 1/2 − θ²/48 + θ⁴/3840 − …
  const double f =
      t2 < kSO3Taylor2 ? 0.5 - t2 / 48.0 * (1.0 - t2 / 80.0) : std::sin(0.5 * theta) / theta;
  Vec4 q;
  q << std::cos(0.5 * theta), f * w;
  return q;
}

/// Rotation vector w (rad, |w| ≤ π) of a quaternion: inverse of QuatFromAxisAngle up to the sign
/// of q (q is first flipped to w ≥ 0). Depends only on the direction of q, so a slightly non-unit
/// q is fine.
inline Vec3 QuatToAxisAngle(const Vec4& q_in) {
  const Vec4 q = q_in[0] < 0.0 ? Vec4(-q_in) : q_in;
  const Vec3 u = q.tail<3>();
  const double n2 = u.squaredNorm();
  const double n = std::sqrt(n2);
  // θ / |u| = 2 atan2(|u|, w) / |u|; for small |u|/w use 2/w (1 − x²/3 + x⁴/5), x = |u|/w.
  if (n2 < kSO3Taylor2 * q[0] * q[0]) {
    const double x2 = n2 / (q[0] * q[0]);
    return (2.0 / q[0] * (1.0 - x2 / 3.0 + x2 * x2 / 5.0)) * u;
  }
  return (2.0 * std::atan2(n, q[0]) / n) * u;
}

/// Rotates x by the unit quaternion q: q ⊗ [0, x] ⊗ q*, computed as
/// x + 2w (u × x) + 2 u × (u × x). Equals QuatToRotation(q) * x.
inline Vec3 QuatRotate(const Vec4& q, const Vec3& x) {
  const Vec3 u = q.tail<3>();
  const Vec3 t = 2.0 * u.cross(x);
  return x + q[0] * t + u.cross(t);
}

}  // namespace cosserat::lie
