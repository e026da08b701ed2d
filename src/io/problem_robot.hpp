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

/// Sets problem->robot and the tendons of problem->rod from `robot`, reporting every error. Call
/// after the rod is parsed (offsets are checked against its section).
void ParseRobot(const ObjectReader& robot, const nlohmann::json& top, Problem* problem);

}  // namespace cosserat::io::detail
