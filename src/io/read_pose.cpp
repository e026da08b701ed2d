#include "read_pose.hpp"

#include <Eigen/Dense>

namespace cosserat::io::detail {
namespace {

constexpr double kRotationTolerance = 1e-6;

/// The rotation nearest to M (polar decomposition), so a matrix accepted within the tolerance
/// reaches the solver exactly orthonormal.
Mat3 NearestRotation(const Mat3& M) {
  Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace

std::optional<Mat3> ReadRotation(const ObjectReader& o, const std::string& key) {
  const auto M = ReadMatrix3(o, key, Presence::kOptional);
  if (!M) return std::nullopt;
  const double orthogonality = (M->transpose() * *M - Mat3::Identity()).cwiseAbs().maxCoeff();
  const double det = M->determinant();
  if (!(orthogonality <= kRotationTolerance && det > 0)) {
    o.report().Expected(o.PathOf(key),
                        "a rotation matrix (orthonormal within 1e-6, i.e. max |R^T R - I| <= "
                        "1e-6, with determinant +1)",
                        "max |R^T R - I| = " + FormatNumber(orthogonality) + " and determinant " +
                            FormatNumber(det));
    return std::nullopt;
  }
  return NearestRotation(*M);
}

lie::SE3 ReadPose(const ObjectReader& o) {
  lie::SE3 pose;
  pose.p = ReadVec3(o, "position", Presence::kOptional).value_or(Vec3::Zero());
  pose.R = ReadRotation(o, "rotation").value_or(Mat3::Identity());
  return pose;
}

}  // namespace cosserat::io::detail
