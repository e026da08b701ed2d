#include "cosserat/lie/quaternion.hpp"

#include <cmath>

namespace cosserat::lie {

Mat3 QuatToRotation(const Vec4& q) {
  const double w = q[0];
  const Vec3 u = q.tail<3>();
  return (w * w - u.squaredNorm()) * Mat3::Identity() + 2.0 * u * u.transpose() + 2.0 * w * hat(u);
}

Vec4 RotationToQuat(const Mat3& R) {
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

Vec4 QuatFromAxisAngle(const Vec3& w) {
  const double t2 = w.squaredNorm();
  const double theta = std::sqrt(t2);
  // sin(θ/2)/θ = 1/2 − θ²/48 + θ⁴/3840 − …
  const double f =
      t2 < kSO3Taylor2 ? 0.5 - t2 / 48.0 * (1.0 - t2 / 80.0) : std::sin(0.5 * theta) / theta;
  Vec4 q;
  q << std::cos(0.5 * theta), f * w;
  return q;
}

Vec3 QuatToAxisAngle(const Vec4& q_in) {
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

}  // namespace cosserat::lie
