#pragma once
// Checks the Python module's objects share: what a problem must be for them to run it.

#include <pybind11/pybind11.h>

#include <string>

#include "cosserat/io/problem.hpp"

namespace cosserat::python {

/// What the module's objects cannot run, refused by the field that asks for it: the
/// quaternion-FD formulation (solve() runs it), eversion growth and displacement control of
/// tendons (solve() and the CLI run them).
inline const io::Problem& Runnable(const io::Problem& problem, const char* what) {
  if (problem.formulation != io::Formulation::kSe3Shooting)
    throw pybind11::value_error(std::string("formulation: ") + what + " runs \"se3-shooting\", got \"" +
                          io::ToString(problem.formulation) + "\" (cosserat.solve runs it)");
  if (problem.has_robot && problem.robot.kind == io::RobotKind::kEversion)
    throw pybind11::value_error(std::string("robot.kind: ") + what +
                          " does not grow an eversion robot (cosserat.solve does)");
  if (problem.robot.tendon_lengths)
    throw pybind11::value_error(std::string("robot.actuation.length: ") + what +
                          " takes tensions, not tendon lengths (cosserat.solve solves for them)");
  return problem;
}

}  // namespace cosserat::python
