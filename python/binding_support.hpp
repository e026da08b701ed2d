#pragma once
// What the module's bindings share: checked base motion, a RodState as NumPy arrays, and the
// fields of the static and step summaries.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat::python {

namespace py = pybind11;

/// Base motion from Python, checked: finite values (rotations: python::Rotation).
template <typename Matrix>
const Matrix& Finite(const Matrix& m, const char* field) {
  if (!m.allFinite()) throw py::value_error(std::string(field) + ": expected finite numbers");
  return m;
}

/// A base position from Python by the problem file's rule: finite, and within
/// io::kFarthestPointInRodLengths of the origin (beyond, the shot "converges" on a straight rod).
inline Vec3 BasePosition(const Vec3& p, double rod_length) {
  Finite(p, "base_position");
  const double far = io::kFarthestPointInRodLengths * rod_length;
  const double away = p.cwiseAbs().maxCoeff();
  if (away > far) {
    std::ostringstream m;
    m << std::setprecision(6) << "base_position: expected a point within 1e9 rod lengths ("
      << far << " m) of the origin, where a double still resolves the rod's shape, got " << away
      << " m away";
    throw py::value_error(m.str());
  }
  return p;
}

inline Eigen::MatrixXd Stack(const std::vector<Vec3>& v) {
  Eigen::MatrixXd out(v.size(), 3);
  for (size_t i = 0; i < v.size(); ++i) out.row(i) = v[i].transpose();
  return out;
}
inline Eigen::MatrixXd Stack(const std::vector<Vec6>& v) {
  Eigen::MatrixXd out(v.size(), 6);
  for (size_t i = 0; i < v.size(); ++i) out.row(i) = v[i].transpose();
  return out;
}

/// What a restored run applies next: the saved run's inputs. A snapshot of the state at rest,
/// before any step, holds the inputs of the equilibrium (the preload): the steps apply the
/// problem's (`first`), as after initialize_at_rest, with the base where the rest state had it.
inline StepInput InputToContinue(const Bdf2ShootingStepper::Snapshot& snapshot,
                                 const StepInput& first) {
  if (snapshot.time != 0.0) return snapshot.last_input;
  StepInput input = first;
  input.base_pose = snapshot.last_input.base_pose;
  return input;
}

/// A RodState as a dict of arrays: s (N), position (N×3), rotation (N×3×3 as a list of 3×3),
/// strain_B, wrench_B, twist_B (N×6).
inline py::dict StateDict(const RodState& state) {
  py::dict d;
  d["s"] = Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(state.s.data(), state.s.size()));
  d["position"] = Stack(state.position_W);
  py::array_t<double> rotation({state.size(), 3, 3});
  auto r = rotation.mutable_unchecked<3>();
  for (int i = 0; i < state.size(); ++i)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) r(i, a, b) = state.rotation_WB[i](a, b);
  d["rotation"] = rotation;
  d["strain_B"] = Stack(state.strain);
  d["wrench_B"] = Stack(state.wrench_B);
  d["twist_B"] = Stack(state.twist_B);
  return d;
}

/// The fields the static and the step summaries share; `extra` gives the repr's text for the
/// summary's own fields (", name=value" each).
template <typename Summary, typename Extra>
py::class_<Summary>& BindSummary(py::class_<Summary>& c, Extra extra) {
  const std::string name = py::str(c.attr("__name__"));
  return c.def_property_readonly("status", [](const Summary& s) { return ToString(s.status); })
      .def_property_readonly("converged", &Summary::converged)
      .def_readonly("iterations", &Summary::iterations)
      .def_readonly("shots", &Summary::shots)
      .def_readonly("residual", &Summary::residual)
      .def_readonly("wall_time_s", &Summary::wall_time_s)
      .def("__repr__", [name, extra](const Summary& s) {
        std::ostringstream o;
        o << std::setprecision(3) << name << "(status=" << ToString(s.status)
          << ", iterations=" << s.iterations << ", shots=" << s.shots << ", residual=" << s.residual
          << ", wall_time_s=" << s.wall_time_s << extra(s) << ")";
        return o.str();
      });
}

}  // namespace cosserat::python
