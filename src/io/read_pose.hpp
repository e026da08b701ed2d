#pragma once
/// \file
/// Poses in a problem file: a "position" [x, y, z] (m, world or a body's frame) and a "rotation"
/// (3 rows of 3, row-major), accepted when orthonormal within 1e-6 with determinant +1 and then
/// made exactly orthonormal.

#include <optional>
#include <string>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/lie/se3.hpp"

namespace cosserat::io::detail {

/// The rotation at `key` (optional), the nearest rotation to the matrix given; nullopt when
/// absent or reported.
std::optional<Mat3> ReadRotation(const ObjectReader& o, const std::string& key);

/// "position" and "rotation" of `o` (both optional: origin, identity), the other keys unchecked.
lie::SE3 ReadPose(const ObjectReader& o);

}  // namespace cosserat::io::detail
