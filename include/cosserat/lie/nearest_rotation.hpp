#pragma once
/// \file
/// Rotation matrices given by people and sensors: accepted when orthonormal within
/// kRotationTolerance with determinant +1 (a matrix typed to 7 digits, or sent as float32, is
/// off by ~1e-7), then replaced by the nearest exact rotation so that solvers see one.

#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "cosserat/lie/types.hpp"

namespace cosserat::lie {

/// The largest max |RᵀR − I| accepted as a rotation.
inline constexpr double kRotationTolerance = 1e-6;

/// max |MᵀM − I| over the entries.
inline double OrthonormalityError(const Mat3& M) {
  return (M.transpose() * M - Mat3::Identity()).cwiseAbs().maxCoeff();
}

/// Orthonormal within kRotationTolerance, with determinant > 0 (NaN fails).
inline bool IsNearlyRotation(const Mat3& M) {
  return OrthonormalityError(M) <= kRotationTolerance && M.determinant() > 0;
}

/// Throws std::invalid_argument naming `what` unless M is finite and IsNearlyRotation: a solver
/// handed 2·I as a rotation would integrate a rod stretched twice over and call it converged.
inline void RequireRotation(const Mat3& M, const char* what) {
  if (!M.allFinite() || IsNearlyRotation(M)) return;  // NaN is the solvers' non_finite status
  std::ostringstream msg;
  msg << what << " is not a rotation: max |R^T R - I| = " << OrthonormalityError(M)
      << ", det R = " << M.determinant() << " (accepted: within " << kRotationTolerance
      << ", det > 0)";
  throw std::invalid_argument(msg.str());
}

/// The rotation nearest to M in the Frobenius norm (polar decomposition, M = U Σ Vᵀ → U Vᵀ).
inline Mat3 NearestRotation(const Mat3& M) {
  Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace cosserat::lie
