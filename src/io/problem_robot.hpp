#pragma once
/// \file
/// The "robot" object of a problem file: the robot kind, its tendons, its chambers
/// (problem_chambers.hpp) and its actuation
/// (docs/problem-format.md#robot).

#include <optional>
#include <string>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// An array of exactly 2 finite numbers at `key` (an offset in the section: body x, y, m), or
/// nullopt (reported; a missing key too).
std::optional<Vec2> ReadOffset(const ObjectReader& o, const std::string& key);

/// The outline tendons and chambers must stay within, from rod.section: a disc (circle,
/// annulus: the outer radius) or a rectangle (half width along body x, half height along body
/// y). Empty for an explicit section (no outline to check against) or a size reported as wrong.
struct Outline {
  std::optional<double> radius;     ///< m
  std::optional<Vec2> half_extent;  ///< m
};
Outline SectionOutline(const nlohmann::json& top);

/// Sets problem->robot and the tendons of problem->rod from `robot`, reporting every error. Call
/// after the rod is parsed (offsets are checked against its section).
void ParseRobot(const ObjectReader& robot, const nlohmann::json& top, Problem* problem);

}  // namespace cosserat::io::detail
