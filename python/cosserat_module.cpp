// The `cosserat` Python module (pybind11): problem files, any problem run as `cosserat solve`
// runs it, the static shooting solver and the BDF2 dynamics stepper, for notebooks and Python
// controllers. Arrays are NumPy, SI units, world frame
// unless a name says _B (body frame). docs/python.md has the tour.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "batch_bindings.hpp"
#include "bend_radius_bindings.hpp"
#include "binding_support.hpp"
#include "interrupt.hpp"
#include "stepper_bindings.hpp"
#include "cosserat/io/problem.hpp"
#include "problem_checks.hpp"
#include "cosserat/run/grid_resolution.hpp"
#include "cosserat/run/run.hpp"
#include "cosserat/run/run_dynamics.hpp"
#include "cosserat/run/run_statics.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace py = pybind11;
using namespace cosserat;
using cosserat::python::BindBatches;
using cosserat::python::BindBendRadius;
using cosserat::python::BindStepper;
using cosserat::python::BindSummary;
using cosserat::python::Finite;
using cosserat::python::StateDict;
using cosserat::python::Rotation;
using cosserat::python::Runnable;
using cosserat::python::Valid;

namespace {

/// Parse errors become one ValueError naming every field at fault, as the CLI prints them.
[[noreturn]] void ThrowErrors(const std::vector<std::string>& errors) {
  std::string message;
  for (const std::string& e : errors) message += (message.empty() ? "" : "\n") + e;
  throw py::value_error(message);
}
io::Problem Checked(io::ParseResult parsed) {
  if (!parsed.ok()) ThrowErrors(parsed.errors);
  return *parsed.problem;
}

LoadFrame FrameFromString(const std::string& name, const char* field) {
  if (name == "world") return LoadFrame::kWorld;
  if (name == "body") return LoadFrame::kBody;
  throw py::value_error(std::string(field) + ": expected \"world\" or \"body\", got \"" + name +
                        "\"");
}
const char* ToString(LoadFrame frame) { return frame == LoadFrame::kWorld ? "world" : "body"; }

/// A fixed-size field of doubles (an Actuation's std::array, a StaticLoads' Vec3) as a writable
/// NumPy view that keeps its owner alive: `a.tendon_tension[0] = 2` and `l.tip_force[0] = 1` set
/// the field, as the C++ idiom does (a copy made that a silent no-op).
template <class Owner, class Field>
auto ViewGetter(Field Owner::*field) {
  return [field](py::object self) {
    Owner& owner = self.cast<Owner&>();
    return py::array_t<double>({static_cast<py::ssize_t>((owner.*field).size())},
                               {sizeof(double)}, (owner.*field).data(), self);
  };
}

/// An Actuation's list field back from a sequence of at most N numbers (zero-filled).
/// A sequence of numbers; a TypeError naming the field for anything else, a ValueError naming
/// the entry for a bool.
std::vector<double> Numbers(const py::object& value, const std::string& name) {
  // A bool is no number (a file's `true` is refused too), which the cast below reads as 1.
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    const py::object numpy_bool = py::module_::import("numpy").attr("bool_");
    std::size_t i = 0;
    for (const py::handle item : value) {
      if (py::isinstance<py::bool_>(item) || py::isinstance(item, numpy_bool))
        throw py::value_error(name + "[" + std::to_string(i) + "]: expected a number, got " +
                              py::repr(item).cast<std::string>());
      ++i;
    }
  }
  try {
    return value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw py::type_error(name + ": expected a list of numbers, got " +
                         py::repr(value).cast<std::string>());
  }
}

template <size_t N>
auto ArraySetter(std::array<double, N> Actuation::*field, const char* name) {
  return [field, name](Actuation& a, const py::object& value) {
    const std::vector<double> values = Numbers(value, name);
    if (values.size() > N)
      throw py::value_error(std::string(name) + ": expected at most " + std::to_string(N) +
                            " values, got " + std::to_string(values.size()));
    (a.*field).fill(0.0);
    std::copy(values.begin(), values.end(), (a.*field).begin());
  };
}

/// A StaticLoads' vector field back from three numbers.
auto Vec3Setter(Vec3 StaticLoads::*field, const char* name) {
  return [field, name](StaticLoads& l, const py::object& value) {
    const std::vector<double> v = Numbers(value, name);
    if (v.size() != 3)
      throw py::value_error(std::string(name) + ": expected 3 numbers, got " +
                            std::to_string(v.size()));
    l.*field = Vec3(v[0], v[1], v[2]);
  };
}

/// [x, y, z] with 6 significant digits, for the reprs.
std::string Text(const Vec3& x) {
  std::ostringstream o;
  o << std::setprecision(6) << "[" << x(0) << ", " << x(1) << ", " << x(2) << "]";
  return o.str();
}

/// The first n values of a list, with 6 significant digits, for the reprs.
template <size_t N>
std::string Text(const std::array<double, N>& values, size_t n) {
  std::ostringstream o;
  o << std::setprecision(6) << "[";
  for (size_t i = 0; i < n && i < N; ++i) o << (i ? ", " : "") << values[i];
  o << "]";
  return o.str();
}

/// The index past the last non-zero value (0 when all are zero).
template <size_t N>
size_t Used(const std::array<double, N>& values) {
  size_t n = 0;
  for (size_t i = 0; i < N; ++i)
    if (values[i] != 0.0) n = i + 1;
  return n;
}

/// The static solver with the problem's clamp pose and loads as defaults.
class PyStaticSolver {
 public:
  explicit PyStaticSolver(const io::Problem& problem)
      : problem_(Runnable(problem, "StaticSolver")),
        solver_(problem.rod, problem.nodes, run::StaticOptions(problem), problem.robot.actuation),
        base_(problem.base),
        loads_(problem.loads) {
    if (problem.boundary != io::Boundary::kCantilever)
      throw py::value_error("boundary: StaticSolver solves a cantilever, got \"" +
                            io::ToString(problem.boundary) +
                            "\" (cosserat.solve runs the other ends)");
    // A rod whose single shot grows too fast (stiff contact, a foundation, tension): multiple
    // shooting in the pieces it chooses, as the CLI solves it (run_statics.cpp).
    if (problem.rod.tendons.empty() && !problem.has_robot &&
        StaticShootingExponent(problem.rod, problem.loads) > 10.0) {
      const StaticShootingOptions single = run::StaticOptions(problem);
      StaticMultipleShootingOptions options;
      options.tolerance = single.tolerance;
      options.max_iterations = single.max_iterations;
      multiple_.emplace(problem.rod, problem.nodes, options);
    }
  }

  /// Every argument is checked before any is applied: a refused call changes nothing.
  StaticShootingSummary Solve(std::optional<StaticLoads> loads, std::optional<Vec3> position,
                              std::optional<Mat3> rotation, std::optional<Actuation> actuation) {
    const StaticLoads next_loads = loads ? Valid(*loads) : loads_;
    lie::SE3 next_base = base_;
    if (position) next_base.p = python::BasePosition(*position, problem_.rod.length);
    if (rotation) next_base.R = Rotation(*rotation, "base_rotation");
    if (actuation) Valid(*actuation, problem_);
    if (actuation && multiple_)
      throw py::value_error(
          "actuation: this rod is solved by multiple shooting (its single shot grows too fast), "
          "which keeps the problem's actuation");
    loads_ = next_loads;
    base_ = next_base;
    if (actuation) solver_.SetActuation(*actuation);
    StaticShootingSummary s =
        multiple_ ? multiple_->Solve(base_, loads_) : solver_.Solve(base_, loads_);
    const RodState& shot = multiple_ ? multiple_->state() : solver_.state();
    if (s.converged() || shot.RanAway()) CheckGrid(&s);  // a runaway is said, not only counted
    // A tendon robot's shot that failed short of running away: the CLI's hint, as a warning.
    if (!shot.RanAway()) Warn(run::TendonLawHint(problem_, solver_.actuation(), s.status));
    last_status_ = s.status;
    return s;
  }
  /// The CLI's check of the grid against the solved shape (run/grid_resolution.hpp): a shot that
  /// ran away is non_finite, a coarse grid a RuntimeWarning.
  void CheckGrid(StaticShootingSummary* s) const {
    const RodState& state = multiple_ ? multiple_->state() : solver_.state();
    const run::GridResolution g = run::CheckGrid(state, problem_.rod.length);
    if (g.ran_away) s->status = SolveStatus::kNonFinite;
    Warn(g.log);
  }
  /// The CLI's log lines, as one RuntimeWarning without their "cosserat: ..." prefixes.
  static void Warn(const std::string& log) {
    std::string text, line;
    std::istringstream lines(log);
    while (std::getline(lines, line)) {
      for (const char* prefix : {"cosserat: warning: ", "cosserat: hint: ", "cosserat: "})
        if (line.rfind(prefix, 0) == 0) line.erase(0, std::string(prefix).size());
      if (!line.empty()) text += (text.empty() ? "" : "\n") + line;
    }
    if (text.empty()) return;
    if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 2) < 0) throw py::error_already_set();
  }
  /// The equilibrium of the last solve(); refused when it did not converge (the solver's state
  /// is then a load step's, not an equilibrium of what was asked).
  const RodState& state() const {
    if (last_status_ == SolveStatus::kNotRun)
      throw std::runtime_error("StaticSolver has no solution yet: call solve() first");
    if (last_status_ != SolveStatus::kConverged)
      throw std::runtime_error(std::string("StaticSolver has no solution: the last solve() "
                                           "ended with status ") +
                               ToString(last_status_));
    return multiple_ ? multiple_->state() : solver_.state();
  }
  /// Shooting pieces: 1, or those of multiple shooting's last solve.
  int pieces() const { return multiple_ ? multiple_->pieces() : 1; }
  /// The tendons' path lengths at the last equilibrium (m), one per tendon.
  Eigen::VectorXd TendonLengths() const {
    state();  // refuses without a converged solve
    const int n = solver_.tendon_count();
    return Eigen::Map<const Eigen::VectorXd>(solver_.tendon_lengths().data(), n);
  }
  /// d(tip pose)/d(tensions) at the last equilibrium: 6 × tendons, [dp (m/N); dθ (rad/N)].
  Eigen::MatrixXd TensionJacobian() const {
    state();
    StaticShootingSolver::TensionJacobian J;
    if (!solver_.TipJacobianWrtTensions(base_, loads_, &J))
      throw std::runtime_error("tension_jacobian: this rod has no tendons");
    return J.leftCols(solver_.tendon_count());
  }

 private:
  io::Problem problem_;  ///< for the actuation's rules (tendons, chambers, jamming segments)
  StaticShootingSolver solver_;
  std::optional<StaticMultipleShootingSolver> multiple_;  ///< rods one shot cannot follow
  lie::SE3 base_;
  StaticLoads loads_;
  SolveStatus last_status_ = SolveStatus::kNotRun;
};

/// cosserat.Fluid: the fluid around the rod (environment.fluid of a problem file).
void BindFluid(py::module_& m) {
  py::class_<Fluid>(m, "Fluid",
                    "The fluid around the rod: density (kg/m³), a uniform flow velocity (m/s, "
                    "world), the Morison coefficients drag_normal, drag_tangential, added_mass "
                    "and the drag diameter (m; 0: the section's). A sheared profile is set from "
                    "a problem file.")
      .def(py::init<>())
      .def_readwrite("density", &Fluid::density)
      .def_readwrite("velocity", &Fluid::velocity_W)
      .def_readwrite("drag_normal", &Fluid::drag_normal)
      .def_readwrite("drag_tangential", &Fluid::drag_tangential)
      .def_readwrite("added_mass", &Fluid::added_mass)
      .def_readwrite("diameter", &Fluid::diameter)
      .def("__repr__", [](const Fluid& f) {
        std::ostringstream o;
        o << std::setprecision(6) << "Fluid(density=" << f.density
          << ", velocity=" << Text(f.velocity_W) << ", drag_normal=" << f.drag_normal
          << ", drag_tangential=" << f.drag_tangential << ", added_mass=" << f.added_mass
          << ", diameter=" << f.diameter << ")";
        return o.str();
      });
}

/// cosserat.Loads: the external loads, their frames and a readable repr.
void BindLoads(py::module_& m) {
  BindFluid(m);
  py::class_<StaticLoads>(m, "Loads",
                          "External loads: gravity (m/s²), a uniform distributed "
                          "force (N/m), a tip force (N) and moment (N·m), and the fluid "
                          "around the rod (buoyancy, drag, added mass). Fields may be given "
                          "as keywords: Loads(gravity=[0, 0, -9.81], tip_force=[0, 0.1, 0]).")
      .def(py::init([](const py::kwargs& fields) {
             py::object loads = py::cast(StaticLoads{});
             for (const auto& [key, value] : fields) {
               const std::string name = py::str(key);
               if (name.rfind("__", 0) == 0 || !py::hasattr(loads, name.c_str()))
                 throw py::type_error("Loads: unknown field '" + name +
                                      "' (fields: gravity, distributed_force, tip_force, "
                                      "tip_moment, tip_force_frame, tip_moment_frame, fluid)");
               loads.attr(name.c_str()) = value;
             }
             return loads.cast<StaticLoads>();
           }))
      // copy.copy(p.loads): a Loads of one's own to change (p.loads is the problem's).
      .def("__copy__", [](const StaticLoads& l) { return l; })
      .def("__deepcopy__", [](const StaticLoads& l, py::dict) { return l; })
      .def_readwrite("fluid", &StaticLoads::fluid)
      .def_property("gravity", ViewGetter(&StaticLoads::gravity_W),
                    Vec3Setter(&StaticLoads::gravity_W, "gravity"),
                    "Gravity, m/s², world frame (a view: editing it in place changes it).")
      .def_property("distributed_force", ViewGetter(&StaticLoads::distributed_force_W),
                    Vec3Setter(&StaticLoads::distributed_force_W, "distributed_force"),
                    "A uniform force along the rod, N/m, world frame.")
      .def_property("tip_force", ViewGetter(&StaticLoads::tip_force),
                    Vec3Setter(&StaticLoads::tip_force, "tip_force"),
                    "The force at the tip, N, in tip_force_frame (\"world\", or \"body\": the "
                    "tip section's frame, a follower force).")
      .def_property("tip_moment", ViewGetter(&StaticLoads::tip_moment),
                    Vec3Setter(&StaticLoads::tip_moment, "tip_moment"),
                    "The moment at the tip, N·m, in tip_moment_frame (\"world\" or \"body\").")
      .def_property(
          "tip_force_frame", [](const StaticLoads& l) { return ToString(l.tip_force_frame); },
          [](StaticLoads& l, const std::string& f) {
            l.tip_force_frame = FrameFromString(f, "tip_force_frame");
          })
      .def_property(
          "tip_moment_frame", [](const StaticLoads& l) { return ToString(l.tip_moment_frame); },
          [](StaticLoads& l, const std::string& f) {
            l.tip_moment_frame = FrameFromString(f, "tip_moment_frame");
          })
      .def("__repr__", [](const StaticLoads& l) {
        std::string text = "Loads(gravity=" + Text(l.gravity_W) +
                           ", distributed_force=" + Text(l.distributed_force_W) +
                           ", tip_force=" + Text(l.tip_force) + " (" +
                           ToString(l.tip_force_frame) + "), tip_moment=" + Text(l.tip_moment) +
                           " (" + ToString(l.tip_moment_frame) + ")";
        if (l.fluid.present())
          text += ", fluid=" + py::repr(py::cast(l.fluid)).cast<std::string>();
        return text + ")";
      });
}

/// cosserat._core.Actuation: tendon tensions and pressures (the C++ stiffness_scale, read only by
/// a section profile written in C++, is left out: no profile Python can build reads it).
void BindActuation(py::module_& m) {
  py::class_<Actuation>(m, "Actuation",
                        "What the actuators do: tendon tensions (N, in the robot's tendon order), "
                        "chamber pressures (Pa, gauge, in the robot's chamber order), "
                        "inflation pressure (Pa), jamming pressure per segment (Pa).")
      .def(py::init<>())
      .def("__copy__", [](const Actuation& a) { return a; })
      .def("__deepcopy__", [](const Actuation& a, py::dict) { return a; })
      .def_readwrite("pressure", &Actuation::pressure)
      .def_property("tendon_tension", ViewGetter(&Actuation::tendon_tension),
                    ArraySetter(&Actuation::tendon_tension, "tendon_tension"))
      .def_property("chamber_pressure", ViewGetter(&Actuation::chamber_pressure),
                    ArraySetter(&Actuation::chamber_pressure, "chamber_pressure"))
      .def_property("jamming_pressure", ViewGetter(&Actuation::jamming_pressure),
                    ArraySetter(&Actuation::jamming_pressure, "jamming_pressure"))
      .def("__repr__", [](const Actuation& a) {
        // The lists up to their last non-zero value (they hold 8 or 16, zero-filled).
        std::ostringstream o;
        o << std::setprecision(6) << "Actuation(tendon_tension="
          << Text(a.tendon_tension, Used(a.tendon_tension))
          << ", chamber_pressure=" << Text(a.chamber_pressure, Used(a.chamber_pressure))
          << ", jamming_pressure=" << Text(a.jamming_pressure, Used(a.jamming_pressure))
          << ", pressure=" << a.pressure << ")";
        return o.str();
      });
}

/// cosserat.Problem, read-only views of a validated problem file, and load_problem and
/// parse_problem, which make one.
std::string ProblemRepr(const io::Problem& p) {
  std::ostringstream o;
  o << std::setprecision(6) << "Problem(analysis=" << io::ToString(p.analysis)
    << ", formulation=" << io::ToString(p.formulation);
  if (p.has_assembly)  // each rod has its own ends (`rods`)
    o << ", assembly";
  else
    o << ", boundary=" << io::ToString(p.boundary) << ", length=" << p.rod.length
      << " m, nodes=" << p.nodes;
  o << ")";
  return o.str();
}

/// A single rod's value, None for an assembly.
py::object SingleRod(const io::Problem& p, py::object value) {
  return p.has_assembly ? py::none() : std::move(value);
}

/// The views of a single rod's problem: None for an assembly, whose rods each have their own
/// (`rods`).
void BindSingleRodViews(py::class_<io::Problem>* problem) {
  problem
      ->def_property_readonly("boundary",
                              [](const io::Problem& p) {
                                return SingleRod(p, py::str(io::ToString(p.boundary)));
                              })
      .def_property_readonly("nodes",
                             [](const io::Problem& p) { return SingleRod(p, py::int_(p.nodes)); })
      .def_property_readonly(
          "length", [](const io::Problem& p) { return SingleRod(p, py::float_(p.rod.length)); })
      .def_property_readonly("base_position",
                             [](const io::Problem& p) { return SingleRod(p, py::cast(p.base.p)); })
      .def_property_readonly("base_rotation",
                             [](const io::Problem& p) { return SingleRod(p, py::cast(p.base.R)); })
      .def_property_readonly(
          "rods",
          [](const io::Problem& p) {
            std::vector<std::string> names;
            for (const AssemblyRod& r : p.assembly.assembly.rods) names.push_back(r.name);
            return p.has_assembly ? py::object(py::cast(names)) : py::object(py::none());
          },
          "An assembly's rod names (assembly.rods), None for a single rod.");
}

void BindProblem(py::module_& m) {
  py::class_<io::Problem> problem(m, "Problem",
                                  "A validated problem file (docs/problem-format.md).");
  BindSingleRodViews(&problem);
  problem
      .def_property_readonly("analysis",
                             [](const io::Problem& p) { return io::ToString(p.analysis); })
      .def_property_readonly("formulation",
                             [](const io::Problem& p) { return io::ToString(p.formulation); })
      .def("__copy__", [](const io::Problem& p) { return p; })
      .def("__deepcopy__", [](const io::Problem& p, py::dict) { return p; })
      .def_readwrite("loads", &io::Problem::loads)
      // The problem's own actuation, as `loads` is: `p.actuation.tendon_tension[0] = 2` edits
      // it; solve() checks it. (cosserat/solvers.py fits what is assigned.)
      .def_property(
          "actuation", [](io::Problem& p) -> Actuation& { return p.robot.actuation; },
          [](io::Problem& p, const Actuation& a) { p.robot.actuation = Valid(a, p); },
          py::return_value_policy::reference_internal)
      .def_property_readonly(
          "tendon_count", [](const io::Problem& p) { return p.rod.tendons.size(); },
          "The tendons of the rod (robot.tendons): the length of actuation.tendon_tension.")
      .def_property_readonly(
          "chamber_count", [](const io::Problem& p) { return p.rod.chambers.size(); },
          "The pressurised chambers of the rod (robot.chambers).")
      .def_property_readonly(
          "contact_count", [](const io::Problem& p) { return p.loads.contact.count; },
          "The contact surfaces of the environment (environment.contact).")
      .def_property_readonly("jamming_segment_count", &python::JammingSegments,
                             "The switchable segments of a layer-jamming rod (0 for any other).")
      .def_property(
          "initial_actuation",
          [](io::Problem& p) -> Actuation& { return p.robot.initial_actuation; },
          [](io::Problem& p, const Actuation& a) { p.robot.initial_actuation = Valid(a, p); },
          py::return_value_policy::reference_internal)
      .def_property_readonly("dt", [](const io::Problem& p) { return p.dynamics.dt; })
      .def_property_readonly("duration", [](const io::Problem& p) { return p.dynamics.duration; })
      .def_property_readonly("initial_loads", [](const io::Problem& p) {
        return p.dynamics.initial_loads.value_or(p.loads);
      })
      .def_property_readonly(
          "section_stiffness",
          [](const io::Problem& p) {
            if (p.has_assembly || !p.rod.section)
              throw py::value_error("assembly: section_stiffness is a single rod's");
            const SectionProperties s = p.rod.section->At(0.0, p.robot.actuation);
            return py::make_tuple(s.min_bending_stiffness(),
                                  s.stiffness(2, 2));
          },
          "(EI, GJ) at s = 0 under the file's actuation, N·m²: the smaller bending stiffness and "
          "the torsional one, stiffness profiles and pressure included.")
      .def("__repr__", &ProblemRepr);

  m.def(
      "load_problem", [](const std::string& path) { return Checked(io::LoadProblemFile(path)); },
      py::arg("path"), "Reads and validates a problem file; ValueError names every bad field.");
  m.def(
      "parse_problem",
      [](const std::string& text) { return Checked(io::ParseProblem(text, "<python>")); },
      py::arg("json_text"), "Validates a problem given as JSON text.");
  m.def(
      "_parse_actuation",
      [](const io::Problem& problem, const std::string& text) {
        io::ActuationParse parsed =
            io::ParseActuationObject(nlohmann::json::parse(text), problem);
        if (!parsed.actuation) ThrowErrors(parsed.errors);
        return *parsed.actuation;
      },
      py::arg("problem"), py::arg("json_text"),
      "An Actuation from JSON text with robot.actuation's keys, by the problem file's rules.");
}

/// cosserat.solve: any problem run as `cosserat solve` runs it.
void BindSolve(py::module_& m) {
  m.def(
      "_dynamics_start_warnings",
      [](const io::Problem& problem, std::optional<double> dt) {
        return run::DynamicsStartWarnings(problem, dt.value_or(problem.dynamics.dt));
      },
      py::arg("problem"), py::arg("dt") = py::none(),
      "The warnings the CLI logs before a dynamics run at dt (default: the problem's), one "
      "line each; the steppers raise them as warnings.");
  m.def(
      "solve",
      [](const io::Problem& problem, bool nodes) {
        // Problem.loads and actuation are assignable, and editable in place, from Python.
        Valid(problem.loads);
        Valid(problem.robot.actuation, problem);
        Valid(problem.robot.initial_actuation, problem);
        const std::vector<std::string> unsupported = io::UnsupportedFeatures(problem);
        if (!unsupported.empty()) {
          std::string message;
          for (const std::string& e : unsupported) message += (message.empty() ? "" : "\n") + e;
          throw py::value_error(message);
        }
        run::RunOptions options;
        options.nodes_csv = nodes;
        options.progress = python::InterruptibleProgress();  // Ctrl-C stops a dynamics run
        run::Result result;
        try {
          py::gil_scoped_release release;  // a long run leaves other Python threads going
          result = run::Run(problem, options);
        } catch (const python::Interrupted&) {
          throw py::error_already_set();  // the KeyboardInterrupt Python has set
        }
        py::dict d;
        d["converged"] = result.converged;
        d["result"] = py::module_::import("json").attr("loads")(result.json.dump());
        d["log"] = result.log;
        if (result.json.contains("contact")) {  // as NumPy arrays: N/m per node, N in total
          const py::module_ np = py::module_::import("numpy");
          d["contact_force"] = np.attr("array")(d["result"]["nodes"]["contact_force"]);
          d["contact_total_force"] = np.attr("array")(d["result"]["contact"]["total_force"]);
        }
        if (nodes) d["nodes_csv"] = result.nodes_csv;
        return d;
      },
      py::arg("problem"), py::arg("nodes") = false,
      "Runs the problem exactly as `cosserat solve` does (any analysis, either formulation, the "
      "robots): a dict with converged, result (the result JSON as a dict), log (the summary "
      "line and hints), with nodes=True nodes_csv (the --csv table as text), and with contact "
      "surfaces contact_force (N x 3, N/m per node) and contact_total_force (N) as NumPy "
      "arrays.");
}

/// cosserat.StaticSolver and its StaticSummary.
void BindStaticSolver(py::module_& m) {
  py::class_<StaticShootingSummary> static_summary(
      m, "StaticSummary",
      "How a StaticSolver solve went: status, Newton iterations, shots, residual, wall time "
      "(s), load steps of the continuation and the stability index (unstable directions: 0 "
      "stable, > 0 unstable, -1 not checked).");
  BindSummary(static_summary,
              [](const StaticShootingSummary& s) {
                return ", load_steps=" + std::to_string(s.load_steps) +
                       ", stability_index=" + std::to_string(s.stability_index);
              })
      .def_readonly("load_steps", &StaticShootingSummary::load_steps)
      .def_readonly("stability_index", &StaticShootingSummary::stability_index);

  py::class_<PyStaticSolver>(m, "StaticSolver",
                             "Static equilibrium of the problem's cantilever (SE(3) shooting); "
                             "re-solves warm-start from the last solution.")
      .def(py::init<const io::Problem&>(), py::arg("problem"),
           "The problem's rod, grid, ends and solver options; nothing is solved until solve().")
      .def("solve", &PyStaticSolver::Solve, py::arg("loads") = py::none(),
           py::arg("base_position") = py::none(), py::arg("base_rotation") = py::none(),
           py::arg("actuation") = py::none(),
           "Solves for the loads, clamp pose and actuation given; what is not given keeps its "
           "last value, at first the problem's loads, base and robot actuation.")
      .def_property_readonly("pieces", &PyStaticSolver::pieces,
                             "Shooting pieces of the last solve: 1, or more for a rod whose "
                             "single shot grows too fast (stiff contact, a foundation, tension).")
      .def(
          "state", [](const PyStaticSolver& s) { return StateDict(s.state()); },
          "The equilibrium of the last solve(), as Stepper.state(); RuntimeError when it did "
          "not converge.")
      .def_property_readonly("tendon_lengths", &PyStaticSolver::TendonLengths,
                             "The tendons' path lengths at the last equilibrium (m), in the "
                             "robot's tendon order.")
      .def("tension_jacobian", &PyStaticSolver::TensionJacobian,
           "d(tip pose)/d(tendon tensions) at the last equilibrium, exact for the discrete "
           "model: a 6 × tendons array, rows d p(L) (world, m/N) then d θ (rad/N) in the tip "
           "section's own body frame, a right perturbation: R(L)(τ + dτ) ≈ R(L) Exp(Σ dθ_i "
           "dτ_i).");
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "Cosserat rods for soft and continuum robots: statics and BDF2 dynamics (SE(3) "
      "shooting) from problem files.";
  m.attr("__version__") = COSSERAT_VERSION_STRING;
  BindLoads(m);
  BindActuation(m);
  BindProblem(m);
  BindSolve(m);
  BindStaticSolver(m);
  BindStepper(m);
  BindBatches(m);
  BindBendRadius(m);
}
