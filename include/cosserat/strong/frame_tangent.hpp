#pragma once
// Internal to the shooting solvers (namespace internal): algebra of tangents (derivatives along 6
// unknowns, one column each) of the quantities a shot carries, with the rotation R stored as its
// three columns d(R e_j). Used to propagate exact Jacobians through RK4.

#include <Eigen/Geometry>
#include <array>

#include "cosserat/lie/types.hpp"

namespace cosserat::internal {

using Mat36 = Eigen::Matrix<double, 3, 6>;
using RotationTangent = std::array<Mat36, 3>;  // d(R e_j), j = 0, 1, 2

// a × B and A × b, column by column.
inline Mat36 Cross(const Vec3& a, const Mat36& B) {
  Mat36 out;
  for (int k = 0; k < 6; ++k) out.col(k) = a.cross(B.col(k));
  return out;
}
inline Mat36 Cross(const Mat36& A, const Vec3& b) { return -Cross(b, A); }

// B × e_j, column by column.
inline Mat36 CrossUnit(const Mat36& B, int j) {
  const int a = (j + 1) % 3, b = (j + 2) % 3;  // v × e_j has v_b at a and −v_a at b
  Mat36 out;
  out.row(j).setZero();
  out.row(a) = B.row(b);
  out.row(b) = -B.row(a);
  return out;
}

// d(Rᵀ f) for a fixed vector f: rows (dR e_j) · f.
inline Mat36 TransposeTimesFixed(const RotationTangent& dR, const Vec3& f) {
  Mat36 out;
  for (int j = 0; j < 3; ++j) out.row(j) = f.transpose() * dR[j];
  return out;
}

// d(R v) = dR v + R dv.
inline Mat36 RotateTangent(const Mat3& R, const RotationTangent& dR, const Vec3& v,
                           const Mat36& dv) {
  return R * dv + v(0) * dR[0] + v(1) * dR[1] + v(2) * dR[2];
}

// d(R K̂) column j = d(R (K × e_j)) = dR (K × e_j) + R (dK × e_j).
inline RotationTangent RotationRateTangent(const Mat3& R, const RotationTangent& dR, const Vec3& K,
                                           const Mat36& dK) {
  RotationTangent out;
  for (int j = 0; j < 3; ++j)
    out[j] = RotateTangent(R, dR, K.cross(Vec3::Unit(j)), CrossUnit(dK, j));
  return out;
}

}  // namespace cosserat::internal
