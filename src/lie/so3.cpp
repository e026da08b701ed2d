#include "cosserat/lie/so3.hpp"

#include <cmath>

namespace cosserat::lie {

Mat3 SO3Exp(const Vec3& w) { return SO3Exp<double>(w); }
Vec3 SO3Log(const Mat3& R) { return SO3Log<double>(R); }
Mat3 SO3LeftJacobian(const Vec3& w) { return SO3LeftJacobian<double>(w); }
Mat3 SO3RightJacobian(const Vec3& w) { return SO3LeftJacobian<double>(-w); }
Mat3 SO3LeftJacobianInverse(const Vec3& w) { return SO3LeftJacobianInverse<double>(w); }
Mat3 SO3RightJacobianInverse(const Vec3& w) { return SO3LeftJacobianInverse<double>(-w); }

Mat3 SO3TurnedOnto(const Mat3& R, const Vec3& d) {
  const double n = d.norm();
  if (!(n > 0.0)) return R;
  const Vec3 z = R.col(2), e = d / n;
  const Vec3 axis = z.cross(e);
  const double s = axis.norm(), c = z.dot(e);
  if (s < 1e-12) return c > 0.0 ? R : Mat3(R * SO3Exp(Vec3(M_PI, 0.0, 0.0)));
  return SO3Exp(Vec3(axis / s * std::atan2(s, c))) * R;
}

}  // namespace cosserat::lie
