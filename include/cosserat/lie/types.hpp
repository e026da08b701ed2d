#pragma once
/// \file
/// Fixed-size Eigen aliases shared by the whole library.
///
/// Conventions, stated once:
/// - A twist or strain is [ω; v] (angular first), a wrench is [m; n] (moment first).
/// - Quantities are in the body frame unless the name says otherwise (suffix _W = world).
/// - SI units everywhere.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross(), used by the inline Lie and kernel headers

namespace cosserat {

template <typename T>
using Vector3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Matrix3 = Eigen::Matrix<T, 3, 3>;
template <typename T>
using Vector6 = Eigen::Matrix<T, 6, 1>;
template <typename T>
using Matrix6 = Eigen::Matrix<T, 6, 6>;

using Vec3 = Vector3<double>;
using Mat3 = Matrix3<double>;
using Vec2 = Eigen::Matrix<double, 2, 1>;
using Vec4 = Eigen::Matrix<double, 4, 1>;
using Vec6 = Vector6<double>;
using Mat6 = Matrix6<double>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

}  // namespace cosserat
