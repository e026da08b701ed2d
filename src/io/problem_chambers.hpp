#pragma once
/// \file
/// "robot.chambers" of a problem file: the pressurised chambers of a soft pneumatic or hydraulic
/// actuator (docs/problem-format.md#robot, docs/pneumatic.md).

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// Sets problem->rod.chambers from robot.chambers (absent: none), reporting every error: each
/// chamber must lie within rod.section and within [0, L]. Call after the rod is parsed. Returns
/// how many chambers the file lists (valid or not), the count the pressures must match.
int ParseChambers(const ObjectReader& robot, const nlohmann::json& top, Problem* problem);

}  // namespace cosserat::io::detail
