#pragma once
/// \file
/// The "robot" object of a problem file: the robot kind, its tendons and its actuation
/// (docs/problem-format.md#robot).

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// Sets problem->robot and the tendons of problem->rod from `robot`, reporting every error. Call
/// after the rod is parsed (offsets are checked against its section).
void ParseRobot(const ObjectReader& robot, const nlohmann::json& top, Problem* problem);

}  // namespace cosserat::io::detail
