// cosserat._minimum_bend_radius: the smallest radius of curvature an eversion robot's body
// reaches as a load pattern grows (to the kink, the pattern's end or a failed solve), or at a
// given turn of its tip (analysis/bend_radius.hpp). cosserat/bend_radius.py takes dicts and paths.
#include "bend_radius_bindings.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>

#include "cosserat/analysis/bend_radius.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/robots/eversion_robot.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "problem_checks.hpp"

namespace cosserat::python {
namespace {

namespace py = pybind11;

py::dict MinimumBendRadiusOf(const io::Problem& problem, const StaticLoads& pattern,
                             std::optional<double> length, bool bands, std::optional<double> angle,
                             int steps) {
  const auto* tube = dynamic_cast<const InflatedTubeSection*>(problem.rod.section.get());
  if (!problem.has_robot || problem.robot.kind != io::RobotKind::kEversion || !tube)
    throw py::value_error(
        "robot.kind: the minimum bend radius is an eversion robot's (\"kind\": \"eversion\", "
        "its section an \"inflated\" stiffness profile)");
  Valid(pattern);
  Valid(problem.loads);
  const double L = length.value_or(problem.rod.length);
  if (!(L > 0.0 && L <= problem.rod.length))
    throw py::value_error("length: expected an everted length in (0, rod.length] (" +
                          std::to_string(problem.rod.length) + " m), got " + std::to_string(L));
  if (steps < 1) throw py::value_error("steps: expected at least 1, got " + std::to_string(steps));
  EversionRobotDesign design = DesignFromTube(*tube, problem.rod.length, problem.base);
  if (!bands) design.bands.clear();
  EversionRobot robot(design, L, problem.robot.actuation.pressure);
  robot.SetTailTension(problem.robot.tail_tension);
  BendRadiusResult r;
  {
    py::gil_scoped_release release;
    r = angle ? BendRadiusAtTipAngle(robot, problem.loads, pattern, *angle)
              : MinimumBendRadius(robot, problem.loads, pattern, steps);
  }
  py::dict out;
  out["min_radius"] = r.min_radius;
  out["s"] = r.s;
  out["load_factor"] = r.load_factor;
  out["limit"] = r.limit;
  out["kink_ratio"] = r.kink_ratio;
  out["solves"] = r.solves;
  return out;
}

}  // namespace

void BindBendRadius(py::module_& m) {
  m.def("_minimum_bend_radius", &MinimumBendRadiusOf, py::arg("problem"), py::arg("pattern"),
        py::arg("length") = py::none(), py::arg("bands") = true, py::arg("angle") = py::none(),
        py::arg("steps") = 20,
        "The minimum bend radius of an eversion robot under its problem's loads as `pattern` "
        "grows from 0 to 1 (or to the tip angle `angle`, rad): a dict of min_radius (m), s (m), "
        "load_factor, limit, kink_ratio and solves.");
}

}  // namespace cosserat::python
