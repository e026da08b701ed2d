#include "read_pose.hpp"

#include "cosserat/lie/nearest_rotation.hpp"

namespace cosserat::io::detail {

std::optional<Mat3> ReadRotation(const ObjectReader& o, const std::string& key) {
  const auto M = ReadMatrix3(o, key, Presence::kOptional);
  if (!M) return std::nullopt;
  if (!lie::IsNearlyRotation(*M)) {
    o.report().Expected(o.PathOf(key),
                        "a rotation matrix (orthonormal within 1e-6, i.e. max |R^T R - I| <= "
                        "1e-6, with determinant +1)",
                        "max |R^T R - I| = " + FormatNumber(lie::OrthonormalityError(*M)) +
                            " and determinant " + FormatNumber(M->determinant()));
    return std::nullopt;
  }
  return lie::NearestRotation(*M);
}

lie::SE3 ReadPose(const ObjectReader& o) {
  lie::SE3 pose;
  pose.p = ReadVec3(o, "position", Presence::kOptional).value_or(Vec3::Zero());
  pose.R = ReadRotation(o, "rotation").value_or(Mat3::Identity());
  return pose;
}

}  // namespace cosserat::io::detail
