#include "read_pose.hpp"

#include "cosserat/lie/nearest_rotation.hpp"

namespace cosserat::io::detail {

std::optional<Mat3> ReadRotation(const ObjectReader& o, const std::string& key) {
  const auto M = ReadMatrix3(o, key, Presence::kOptional);
  if (!M) return std::nullopt;
  if (!lie::IsNearlyRotation(*M)) {
    const double error = lie::OrthonormalityError(*M);
    // A rotation typed by hand to five digits (0.70711 for cos 45°) is off by about 1e-5.
    const bool rounded = error < 1e-3 && M->determinant() > 0;
    o.report().Expected(o.PathOf(key),
                        "a rotation matrix (orthonormal within 1e-6, i.e. max |R^T R - I| <= "
                        "1e-6, with determinant +1)",
                        "max |R^T R - I| = " + FormatNumber(error) + " and determinant " +
                            FormatNumber(M->determinant()) +
                            (rounded ? " (entries rounded too far: give them to 7 significant "
                                       "digits or more)"
                                     : ""));
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
