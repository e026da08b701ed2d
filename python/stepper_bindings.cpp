// cosserat.Stepper: the BDF2 dynamics stepper for control loops from Python, with the input it
// applies, its StepSummary and Snapshot.
#include "stepper_bindings.hpp"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "binding_support.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/run/initial_equilibrium.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "problem_checks.hpp"

namespace cosserat::python {
namespace {

/// A column's loads for one step: a ValueError naming the field a guided tip cannot take.
void RequireColumnLoads(const StaticLoads& loads, io::Boundary boundary) {
  std::vector<std::string> refused;
  io::GuidedTipLoadFeatures(loads, boundary, &refused);
  if (!refused.empty()) throw py::value_error(refused.front());
}

/// A column the CLI would run in dynamics: what its dynamics refuse (a body at the guided tip,
/// a bit, ...) is refused here by the same line.
void RequireColumnStepper(const io::Problem& problem) {
  io::Problem in_time = problem;
  in_time.analysis = io::Analysis::kDynamics;
  const std::vector<std::string> refused = io::UnsupportedFeatures(in_time);
  if (!refused.empty()) throw py::value_error(refused.front());
}

/// The dynamics stepper with the input it applies, so that a control loop only says what
/// changed. As the CLI's run: the equilibrium at t = 0 under the problem's initial loads and
/// actuation, the steps under its loads and actuation, unless told otherwise.
class PyStepper {
 public:
  PyStepper(const io::Problem& problem, std::optional<double> dt,
            std::optional<std::string> spatial_scheme)
      : problem_(Steppable(problem, "the Stepper")),
        options_(cosserat::run::DynamicsOptions(problem)) {
    const TipHold column_tip = cosserat::run::GuidedTipHold(problem.boundary);
    if (problem.boundary != io::Boundary::kCantilever &&
        problem.boundary != io::Boundary::kFreeFree && column_tip == TipHold::kFree)
      throw py::value_error("boundary: the Stepper runs \"cantilever\", \"free-free\", "
                            "\"clamped-clamped\" or \"clamped-pinned\", got \"" +
                            io::ToString(problem.boundary) + "\"");
    if (column_tip != TipHold::kFree) RequireColumnStepper(problem);
    if (dt) options_.dt = *dt;
    if (spatial_scheme) {
      io::ShotScheme scheme;
      if (!io::FromString(*spatial_scheme, &scheme))
        throw py::value_error(
            "spatial_scheme: expected \"rk4-pairs\", \"rk4\" or \"heun\", got \"" +
            *spatial_scheme + "\"");
      options_.spatial_scheme = cosserat::run::ToSpatialScheme(scheme);
    }
    std::string why;
    if (!options_.IsValid(&why)) throw py::value_error(why);
    stepper_.emplace(problem.rod, problem.nodes, options_);
    initial_loads_ = problem.dynamics.initial_loads.value_or(problem.loads);
    initial_actuation_ = problem.robot.initial_actuation;
    first_input_.base_pose = problem.base;
    first_input_.loads = problem.loads;
    first_input_.actuation = problem.robot.actuation;
    // A column's tip slides along the clamp's axis, through the clamp (as the CLI runs it).
    first_input_.tip_hold = column_tip;
    if (column_tip != TipHold::kFree) first_input_.tip_pose = problem.base;
    input_ = first_input_;
  }

  StepSummary InitializeAtRest(std::optional<StaticLoads> loads,
                               std::optional<Actuation> actuation) {
    // An episode reset: the rest and the steps after it start from the problem's inputs (its
    // base pose, no base motion), whatever the last run applied.
    StepInput at_rest = first_input_;
    at_rest.loads = loads ? Valid(*loads) : initial_loads_;
    if (at_rest.tip_hold != TipHold::kFree) RequireColumnLoads(at_rest.loads, problem_.boundary);
    at_rest.actuation = actuation ? Valid(*actuation, problem_) : initial_actuation_;
    const StepSummary s =
        cosserat::run::InitializeAtStaticEquilibrium(problem_, at_rest, &*stepper_);
    if (s.converged()) input_ = first_input_;
    // A failed reset leaves no state to show: the last run's would read as this one's (its tip,
    // its time), and step() could not go on from it anyway.
    has_state_ = s.converged();
    failed_reset_ = !s.converged();
    return s;
  }

  /// Every argument is checked before any is applied: a refused call changes nothing.
  StepSummary Step(std::optional<StaticLoads> loads, std::optional<Vec3> base_position,
                   std::optional<Mat3> base_rotation, std::optional<Vec6> base_twist_B,
                   std::optional<Vec6> base_wrench_B, std::optional<Actuation> actuation) {
    run();  // a state to step from
    StepInput next = input_;
    // What is not given keeps the last step's, which `loads` and `actuation` may have edited in
    // place: checked alike.
    next.loads = Valid(loads ? *loads : input_.loads);
    next.actuation = Valid(actuation ? *actuation : input_.actuation, problem_);
    if (next.tip_hold != TipHold::kFree) {
      RequireColumnLoads(next.loads, problem_.boundary);
      if (base_position || base_rotation || base_twist_B)
        throw py::value_error(std::string(base_position   ? "base_position"
                                          : base_rotation ? "base_rotation"
                                                          : "base_twist_B") +
                              ": a column's clamp and the guide of its tip stay where the "
                              "problem puts them");
    }
    if (base_position) next.base_pose.p = BasePosition(*base_position, problem_.rod.length);
    if (base_rotation) next.base_pose.R = Rotation(*base_rotation, "base_rotation");
    if (base_twist_B) next.base_twist_B = Finite(*base_twist_B, "base_twist_B");
    if (base_wrench_B) next.base_wrench_B = Finite(*base_wrench_B, "base_wrench_B");
    input_ = next;
    return stepper_->Step(input_);
  }

  /// The stepper, once it has a state to show (a converged initialize_at_rest or a restore).
  const Bdf2ShootingStepper& run() const {
    if (!has_state_)
      throw std::runtime_error(
          failed_reset_ ? "the Stepper has no state: the last initialize_at_rest() did not "
                          "converge (its status says why); call it again, or restore() a "
                          "snapshot"
                        : "the Stepper has no state yet: call initialize_at_rest() first");
    return *stepper_;
  }
  Bdf2ShootingStepper::Snapshot Save() const { return run().Save(); }
  void Restore(const Bdf2ShootingStepper::Snapshot& snapshot) {
    if (snapshot.last_input.tip_hold != first_input_.tip_hold)
      throw py::value_error("snapshot: taken from a rod with other end conditions (a column's "
                            "guided tip, or a free one)");
    stepper_->Restore(snapshot);  // throws std::invalid_argument (ValueError) if it can't
    input_ = InputToContinue(snapshot, first_input_);
    has_state_ = true;
    failed_reset_ = false;
  }
  double time() const {
    if (failed_reset_) run();  // raises: the last run's time is not this one's
    return stepper_->time();
  }
  int shot_steps() const { return stepper_->shot_steps(); }  // planned at construction
  const StepInput& input() const { return input_; }
  StepInput& input() { return input_; }
  const io::Problem& problem() const { return problem_; }
  const Bdf2Options& options() const { return options_; }

 private:
  io::Problem problem_;  ///< for the actuation's rules (tendons, chambers, jamming segments)
  Bdf2Options options_;
  std::optional<Bdf2ShootingStepper> stepper_;
  StaticLoads initial_loads_;
  Actuation initial_actuation_;
  StepInput first_input_;  ///< what the first step applies: the problem's loads and actuation
  StepInput input_;        ///< what step() applies
  bool has_state_ = false;
  bool failed_reset_ = false;  ///< the last initialize_at_rest() did not converge
};

/// What a Stepper shows of its rod: the state, the tip, the support's wrench, energy, momentum.
void BindStepperOutputs(py::class_<PyStepper>& c) {
  c.def(
       "state", [](const PyStepper& s) { return StateDict(s.run().state()); },
       "The rod now: a dict of s (N, m), position (N×3, m, world), rotation (N×3×3, body to "
       "world), strain_B, wrench_B ([moment; force], N·m and N) and twist_B ([ω; v], rad/s "
       "and m/s), N×6 in each section's body frame.")
      .def(
          "tip_position", [](const PyStepper& s) { return Vec3(s.run().state().tip_position_W()); },
          "The tip's position, m, world frame.")
      .def(
          "tip_rotation",
          [](const PyStepper& s) { return Mat3(s.run().state().tip_rotation_WB()); },
          "The tip section's rotation, body to world.")
      .def(
          "tip_twist_B", [](const PyStepper& s) { return Vec6(s.run().state().twist_B.back()); },
          "The tip's twist [ω; v] (rad/s, m/s) in its body frame.")
      .def(
          "base_reaction", [](const PyStepper& s) { return s.run().state().BaseReaction_W(); },
          "The wrench [moment; force] the support applies at s = 0, world frame.")
      .def(
          "energy",
          [](const PyStepper& s) {
            RodEnergy e = s.run().Energy(s.input().loads);
            const RodEnergy tip = TipBodyEnergy(s.options().tip_mass, s.options().tip_inertia_B,
                                                s.input().loads.gravity_W, s.run().state());
            e.kinetic += tip.kinetic;
            e.potential += tip.potential;
            py::dict d;
            d["kinetic"] = e.kinetic;
            d["elastic"] = e.elastic;
            d["potential"] = e.potential;
            d["total"] = e.total();
            return d;
          },
          "Kinetic, elastic and potential energy (J), the tip body's (dynamics.tip_mass) "
          "included; potential: of the distributed loads step() applies.")
      .def(
          "momentum",
          [](const PyStepper& s) {
            const RodMomentum p = s.run().Momentum();
            const RodMomentum tip =
                TipBodyMomentum(s.options().tip_mass, s.options().tip_inertia_B, s.run().state());
            return py::make_tuple(Vec3(p.linear_W + tip.linear_W),
                                  Vec3(p.angular_W + tip.angular_W));
          },
          "(linear, angular about the origin), world frame, the tip body's included.")
      .def(
          "mass", [](const PyStepper& s) { return s.run().Mass() + s.options().tip_mass; },
          "The rod's mass with its tip body, kg.");
}

/// cosserat.Stepper (BDF2 dynamics for control loops), its StepSummary and Snapshot.
void BindStepperClass(py::module_& m) {
  py::class_<StepSummary> step_summary(
      m, "StepSummary",
      "How a Stepper call went: status, Newton iterations, shots of the rod, residual, wall "
      "time (s), exact Jacobians, the deepest step halving and the multiple-shooting pieces.");
  BindSummary(step_summary,
              [](const StepSummary& s) {
                return ", halvings=" + std::to_string(s.halvings) +
                       ", shooting_segments=" + std::to_string(s.shooting_segments);
              })
      .def_readonly("jacobians", &StepSummary::jacobians)
      .def_readonly("halvings", &StepSummary::halvings)
      .def_readonly("shooting_segments", &StepSummary::shooting_segments,
                    "pieces the rod was shot in (chosen from dt and the tension unless the "
                    "problem sets dynamics.shooting_segments)");

  py::class_<Bdf2ShootingStepper::Snapshot>(m, "Snapshot",
                                            "Everything a Stepper needs to continue a run.");

  py::class_<PyStepper> stepper(
      m, "Stepper",
      "BDF2 dynamics of the problem's rod (cantilever, free-free, or a clamped-clamped or "
      "clamped-pinned column whose tip slides on the clamp's axis), as the CLI runs it: "
      "initialize_at_rest() under the problem's initial loads and actuation, step() under its "
      "loads and actuation unless told otherwise.");
  stepper
      .def(py::init<const io::Problem&, std::optional<double>, std::optional<std::string>>(),
           py::arg("problem"), py::arg("dt") = py::none(), py::arg("spatial_scheme") = py::none(),
           "The problem's rod, grid, ends and dynamics options; dt (s) and spatial_scheme "
           "(\"rk4-pairs\", the default, \"rk4\" or \"heun\") override the file's.")
      .def("initialize_at_rest", &PyStepper::InitializeAtRest, py::arg("loads") = py::none(),
           py::arg("actuation") = py::none(),
           "Static equilibrium at t = 0 under `loads` and `actuation` (default: the problem's "
           "initial loads and initial actuation), found as the CLI finds it: the statics "
           "solver's equilibrium (continuation in the load, pieces for a taut rod) refined on "
           "the stepper's own equations. What step() applies is not changed.")
      .def("step", &PyStepper::Step, py::arg("loads") = py::none(),
           py::arg("base_position") = py::none(), py::arg("base_rotation") = py::none(),
           py::arg("base_twist_B") = py::none(), py::arg("base_wrench_B") = py::none(),
           py::arg("actuation") = py::none(),
           "Advances dt (a step that fails keeps the halved sub-steps it completed: time "
           "then stops short; save() before it to retry from its start). Arguments not given "
           "keep the last step's (at first the problem's "
           "loads, base pose and robot actuation; `loads` and `actuation` as edited in place). "
           "An actuation given is a whole state: a dict or cosserat.Actuation that leaves out "
           "the section's pressures (inflation, jamming) takes the problem file's, not the last "
           "step's. Cantilever: the base pose and twist [w; v] "
           "(body frame) at the end of the step, which must agree (the twist is not derived "
           "from the pose); free-free: the wrench on the s = 0 end (body frame).")
      .def_property_readonly("time", &PyStepper::time, "Simulated time since the rest state, s.")
      .def_property_readonly(
          "dt", [](const PyStepper& s) { return s.options().dt; }, "The step, s.")
      .def_property_readonly(
          "shot_steps", &PyStepper::shot_steps,
          "The steps of the shot in s: the grid's segments less the pairs the default scheme "
          "forms (docs/dynamics.md, \"Choosing the scheme in s\").")
      .def_property(
          "loads", [](PyStepper& s) -> StaticLoads& { return s.input().loads; },
          [](PyStepper& s, const StaticLoads& loads) { s.input().loads = Valid(loads); },
          py::return_value_policy::reference_internal,
          "The loads the next step() applies unless given others: assigned (checked then) or "
          "edited in place (checked at that step), they are its; initialize_at_rest() resets "
          "them to the problem's.")
      .def_property(
          "actuation", [](PyStepper& s) -> Actuation& { return s.input().actuation; },
          [](PyStepper& s, const Actuation& a) { s.input().actuation = Valid(a, s.problem()); },
          py::return_value_policy::reference_internal,
          "The actuation the next step() applies unless given another: `s.actuation."
          "tendon_tension[0] = 2` sets it (checked at that step); initialize_at_rest() resets "
          "it to the problem's.")
      .def("save", &PyStepper::Save,
           "A Snapshot of the run (state, history and inputs) for restore(); allocates.")
      .def("restore", &PyStepper::Restore,
           "Continues the saved run, with the inputs it was applying; a snapshot from another "
           "rod, grid or end conditions, or taken before initialize_at_rest, is refused.");
  BindStepperOutputs(stepper);
}

}  // namespace

void BindStepper(py::module_& m) { BindStepperClass(m); }

}  // namespace cosserat::python
