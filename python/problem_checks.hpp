#pragma once
// Checks the Python module's objects share: what a problem must be for them to run it, and the
// inputs they are given, with the problem file's rules.

#include <pybind11/pybind11.h>

#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/lie/nearest_rotation.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"

namespace cosserat::python {

/// Loads checked before they reach a solver (NaN, Inf): a ValueError naming the field.
inline const StaticLoads& Valid(const StaticLoads& loads) {
  std::string why;
  if (!loads.IsValid(&why)) throw pybind11::value_error("loads: " + why);
  return loads;
}

inline const Actuation& Valid(const Actuation& a, const io::Problem& problem);  // below

/// What the module's objects cannot run, refused by the field that asks for it: assemblies, the
/// quaternion-FD formulation (solve() runs them), eversion growth and displacement control of
/// tendons (solve() and the CLI run them), and loads set on the Problem that no solver runs.
inline const io::Problem& Runnable(const io::Problem& problem, const char* what) {
  if (problem.has_assembly)
    throw pybind11::value_error(std::string("assembly: ") + what +
                                " runs one rod (cosserat.solve runs assemblies)");
  if (problem.formulation != io::Formulation::kSe3Shooting)
    throw pybind11::value_error(std::string("formulation: ") + what + " runs \"se3-shooting\", got \"" +
                          io::ToString(problem.formulation) + "\" (cosserat.solve runs it)");
  if (problem.has_robot && problem.robot.kind == io::RobotKind::kEversion)
    throw pybind11::value_error(std::string("robot.kind: ") + what +
                          " does not run an eversion robot (cosserat.solve grows it, or solves "
                          "its statics at its length)");
  if (problem.robot.tendon_lengths)
    throw pybind11::value_error(std::string("robot.actuation.length: ") + what +
                          " takes tensions, not tendon lengths (cosserat.solve solves for them)");
  // A Problem's loads and actuation set from Python since it was read.
  Valid(problem.loads);
  Valid(problem.robot.actuation, problem);
  Valid(problem.robot.initial_actuation, problem);
  return problem;
}

/// Runnable, and none of the inputs the CLI's run drives in time by itself, which a stepper
/// is given step by step instead: a spinning clamp, a rotary table, a gusting flow.
inline const io::Problem& Steppable(const io::Problem& problem, const char* what) {
  Runnable(problem, what);
  const auto refuse = [&](const char* field, const char* instead) {
    throw pybind11::value_error(std::string(field) + ": " + what +
                                " applies what step() is given; " + instead +
                                " (cosserat.solve runs the file as it is)");
  };
  if (problem.dynamics.base_spin != 0.0)
    refuse("dynamics.base_spin", "turn the clamp with base_rotation and base_twist_B");
  if (problem.dynamics.rotary_table.present())
    refuse("dynamics.rotary_table", "turn the clamp with base_rotation and base_twist_B");
  if (problem.gust.present()) refuse("environment.fluid.gust", "set loads.fluid each step");
  return problem;
}

/// The switchable segments of a layer-jamming rod (0 for any other).
inline int JammingSegments(const io::Problem& problem) {
  const auto* jamming = dynamic_cast<const JammingSection*>(problem.rod.section.get());
  return jamming ? static_cast<int>(jamming->segments().size()) : 0;
}

/// An actuation checked before it reaches a solver, with the rules of the problem file
/// (Actuation::IsValid against the rod's tendons and chambers, and the jamming segments): a
/// ValueError naming the field.
inline const Actuation& Valid(const Actuation& a, const io::Problem& problem) {
  std::string why;
  if (!a.IsValid(&why, static_cast<int>(problem.rod.tendons.size()),
                 static_cast<int>(problem.rod.chambers.size())))
    throw pybind11::value_error("actuation." + why);
  const int segments = JammingSegments(problem);
  for (int k = segments; k < Actuation::kMaxSegments; ++k)
    if (a.jamming_pressure[k] != 0.0)
      throw pybind11::value_error(
          "actuation.jamming_pressure: a pressure on segment " + std::to_string(k) +
          ", but the rod has " + std::to_string(segments) +
          " switchable jamming segments (rod.stiffness_profile of kind \"jamming\")");
  return a;
}

/// A base rotation from Python, with the problem file's rule: orthonormal within 1e-6 with
/// determinant +1, then the nearest exact rotation. A ValueError naming the field otherwise.
inline Mat3 Rotation(const Mat3& R, const char* field) {
  if (!R.allFinite()) throw pybind11::value_error(std::string(field) + ": expected finite numbers");
  if (!lie::IsNearlyRotation(R))
    throw pybind11::value_error(
        std::string(field) +
        ": expected a rotation matrix (orthonormal within 1e-6, i.e. max |R^T R - I| <= 1e-6, "
        "with determinant +1), got max |R^T R - I| = " +
        std::to_string(lie::OrthonormalityError(R)) + " and determinant " +
        std::to_string(R.determinant()));
  return lie::NearestRotation(R);
}

}  // namespace cosserat::python
