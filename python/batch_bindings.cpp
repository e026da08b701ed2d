// cosserat.BatchStepper (M rods stepped together on all cores) and cosserat._core.sweep (a study
// run into a CSV file), for controllers, learning loops and design studies from Python.
#include "batch_bindings.hpp"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <unistd.h>

#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <variant>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/io/study.hpp"
#include "cosserat/run/initial_equilibrium.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/run/sweep.hpp"
#include "cosserat/strong/batch_stepper.hpp"
#include "binding_support.hpp"
#include "interrupt.hpp"
#include "problem_checks.hpp"

namespace py = pybind11;

namespace cosserat::python {
namespace {

/// Refuses a batch whose rods would not fit in half the machine's memory: each node of each rod
/// holds about 3.4 kB (its state, BDF2 history, shot stages and tangents: 138 kB a rod of 41
/// nodes, measured). 1e9 rods were once allocated until the kernel killed the process.
void CheckMemory(int count, int nodes) {
  const double bytes = 3.4e3 * static_cast<double>(count) * nodes;
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  if (memory > 0 && bytes > 0.5 * memory)
    throw py::value_error("count: " + std::to_string(count) + " rods of " +
                          std::to_string(nodes) + " nodes need about " +
                          std::to_string(static_cast<long long>(bytes / 1e9)) +
                          " GB, more than half of this machine's " +
                          std::to_string(static_cast<long long>(memory / 1e9)) + " GB");
}

/// M rods of the problem stepped together on a team of threads (BatchStepper), with inputs and
/// outputs as (M, ...) arrays: each rod starts from the problem's input, as a Stepper does, and
/// step() replaces what it is given, rod by rod.
class PyBatchStepper {
 public:
  PyBatchStepper(const io::Problem& problem, int count, std::optional<int> threads)
      : problem_(Steppable(problem, "the BatchStepper")),
        options_(cosserat::run::DynamicsOptions(problem_)),
        tendons_(static_cast<int>(problem.rod.tendons.size())) {
    if (problem.boundary != io::Boundary::kCantilever)
      throw py::value_error("boundary: the BatchStepper runs \"cantilever\", got \"" +
                            io::ToString(problem.boundary) + "\"");
    if (count < 1) throw py::value_error("count: expected at least 1 rod, got " +
                                         std::to_string(count));
    CheckMemory(count, problem.nodes);
    const int team = threads ? *threads : static_cast<int>(std::thread::hardware_concurrency());
    if (team < 1) throw py::value_error("threads: expected at least 1");
    batch_.emplace(problem.rod, problem.nodes, options_, count, team);
    initial_.base_pose = problem.base;
    initial_.loads = problem.dynamics.initial_loads.value_or(problem.loads);
    initial_.actuation = problem.robot.initial_actuation;
    StepInput input;
    input.base_pose = problem.base;
    input.loads = problem.loads;
    input.actuation = problem.robot.actuation;
    first_inputs_.assign(count, input);
    inputs_ = first_inputs_;
  }

  /// As the Stepper starts: from the statics solver's equilibrium, else the rods' own solve;
  /// the steps after it apply the problem's loads and actuation (as after construction).
  int InitializeAtRest() {
    return Locked([&] {
      const std::optional<RodState> equilibrium =
          cosserat::run::StaticEquilibriumToStartFrom(problem_, initial_);
      int converged = equilibrium ? batch_->InitializeAtRest(initial_, *equilibrium) : 0;
      if (converged != batch_->count()) converged = batch_->InitializeAtRest(initial_);
      initialized_ = converged == batch_->count();
      failed_reset_ = !initialized_;
      if (initialized_) inputs_ = first_inputs_;  // an episode reset: the file's inputs again
      return converged;
    });
  }

  /// tip_force (M, 3) N, world; tension (M, tendons) N. Returns how many rods converged. Both
  /// are checked before either is applied: a refused call changes nothing.
  int Step(std::optional<Eigen::MatrixXd> tip_force, std::optional<Eigen::MatrixXd> tension) {
    const int M = batch_->count();  // fixed at construction
    if (tip_force) Check(*tip_force, M, 3, "tip_force");
    if (tension) {
      Check(*tension, M, tendons_, "tension");
      if ((tension->array() < 0).any()) throw py::value_error("tension: a tendon cannot push");
    }
    return Locked([&] {
      RequireState();
      if (tip_force)
        for (int i = 0; i < M; ++i) inputs_[i].loads.tip_force = tip_force->row(i).transpose();
      if (tension)
        for (int i = 0; i < M; ++i)
          for (int j = 0; j < tendons_; ++j)
            inputs_[i].actuation.tendon_tension[j] = (*tension)(i, j);
      return batch_->Step(inputs_.data());
    });
  }

  std::vector<Bdf2ShootingStepper::Snapshot> Save() const {
    return Locked([&] {
      RequireState();
      return batch_->Save();
    });
  }
  /// Rod i from snapshots[i], or every rod from one snapshot (a Stepper's, for rollouts from a
  /// measured state); each then applies the inputs its run was applying (InputToContinue).
  void Restore(const std::variant<Bdf2ShootingStepper::Snapshot,
                                  std::vector<Bdf2ShootingStepper::Snapshot>>& snapshots) {
    Locked([&] {
      if (const auto* one = std::get_if<Bdf2ShootingStepper::Snapshot>(&snapshots)) {
        batch_->RestoreAll(*one);  // throws std::invalid_argument (ValueError), changing nothing
        inputs_.assign(batch_->count(), InputToContinue(*one, first_inputs_[0]));
      } else {
        const auto& each = std::get<std::vector<Bdf2ShootingStepper::Snapshot>>(snapshots);
        batch_->Restore(each);
        for (int i = 0; i < batch_->count(); ++i)
          inputs_[i] = InputToContinue(each[i], first_inputs_[i]);
      }
      initialized_ = true;
      failed_reset_ = false;
      return 0;
    });
  }

  /// (M, N, 3) node positions, m, world.
  py::array_t<double> Positions() const {
    const int M = batch_->count(), N = batch_->rod(0).state().size();
    std::vector<double> x(static_cast<size_t>(M) * N * 3);  // copied under the lock
    Locked([&] {
      RequireState();
      for (int i = 0; i < M; ++i)
        for (int j = 0; j < N; ++j)
          for (int k = 0; k < 3; ++k)
            x[(static_cast<size_t>(i) * N + j) * 3 + k] = batch_->rod(i).state().position_W[j](k);
      return 0;
    });
    py::array_t<double> out({M, N, 3});
    std::copy(x.begin(), x.end(), out.mutable_data());
    return out;
  }

  Eigen::MatrixXd TipPositions() const {
    return Locked([&] {
      RequireState();
      Eigen::MatrixXd out(batch_->count(), 3);
      for (int i = 0; i < batch_->count(); ++i)
        out.row(i) = batch_->rod(i).state().tip_position_W().transpose();
      return out;
    });
  }
  /// Whether each rod's last step converged (M bools); a rod that failed stays at the last state
  /// it reached, behind the others.
  std::vector<bool> Converged() const {
    return Locked([&] {
      RequireState();
      std::vector<bool> out(batch_->count());
      for (int i = 0; i < batch_->count(); ++i) out[i] = batch_->summary(i).converged();
      return out;
    });
  }
  /// Each rod's simulated time, s (M values).
  std::vector<double> Times() const {
    return Locked([&] {
      if (failed_reset_) RequireState();  // raises: the last run's times are not this one's
      std::vector<double> out(batch_->count());
      for (int i = 0; i < batch_->count(); ++i) out[i] = batch_->rod(i).time();
      return out;
    });
  }
  double time() const {
    return Locked([&] {
      if (failed_reset_) RequireState();
      return batch_->rod(0).time();
    });
  }
  int count() const { return batch_->count(); }

 private:
  /// f() with the GIL let go and the batch locked: a call from another Python thread waits its
  /// turn (a reader during a step, for it to end). step() lets go of the GIL while its rods run,
  /// and two threads in one batch at once had corrupted the heap. f must not touch Python
  /// objects; the lock is released before the GIL is taken back, so no two threads wait on each
  /// other.
  template <typename F>
  std::invoke_result_t<F> Locked(F&& f) const {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    return f();
  }

  /// Every rod at rest after a converged initialize_at_rest (as the Stepper requires).
  void RequireState() const {
    if (!initialized_)
      throw std::runtime_error(
          "the BatchStepper has no state yet: call initialize_at_rest() first (and every rod's "
          "initial equilibrium must converge)");
  }

  static void Check(const Eigen::MatrixXd& a, int rows, int cols, const char* name) {
    if (a.rows() != rows || a.cols() != cols)
      throw py::value_error(std::string(name) + ": expected shape (" + std::to_string(rows) + ", " +
                            std::to_string(cols) + "), got (" + std::to_string(a.rows()) + ", " +
                            std::to_string(a.cols()) + ")");
    if (!a.allFinite()) throw py::value_error(std::string(name) + ": expected finite numbers");
  }

  io::Problem problem_;  ///< for the statics the rods start from
  Bdf2Options options_;
  int tendons_;
  std::optional<BatchStepper> batch_;
  StepInput initial_;
  std::vector<StepInput> first_inputs_;  ///< what the first steps apply: the file's
  std::vector<StepInput> inputs_;
  bool initialized_ = false;
  mutable std::mutex mutex_;  ///< held by the call under way (Locked)
  bool failed_reset_ = false;  ///< the last initialize_at_rest() left a rod unconverged
};

/// cosserat._core.sweep: a study (io/study.hpp) run into a CSV file (run/sweep.hpp).
void BindSweep(py::module_& m) {
  m.def(
      "sweep",
      [](const std::string& study_json, const std::string& base_directory, const std::string& out,
         int threads) {
        const io::StudyParseResult parsed = io::ParseStudy(study_json, "<study>", base_directory);
        if (!parsed.study) {
          std::string message;
          for (const std::string& e : parsed.errors) message += (message.empty() ? "" : "\n") + e;
          throw py::value_error(message);
        }
        run::SweepOptions options;
        options.threads = threads;
        // Ctrl-C stops the sweep after the points under way; their rows stay for a resume.
        InterruptCheck check;
        bool interrupted = false;
        options.keep_going = [&] { return !(interrupted = interrupted || check.Pending()); };
        run::SweepSummary s;
        {
          py::gil_scoped_release release;
          s = run::RunSweep(*parsed.study, out, options);
        }
        if (interrupted) throw py::error_already_set();
        py::dict d;
        d["points"] = s.points;
        d["resumed"] = s.resumed;
        d["ran"] = s.ran;
        d["failed"] = s.failed;
        d["dropped"] = s.dropped;
        d["complete"] = s.complete;
        d["wall_time_s"] = s.wall_time_s;
        d["empty_outputs"] = s.empty_outputs;
        return d;
      },
      py::arg("study_json"), py::arg("base_directory"), py::arg("out"), py::arg("threads"),
      "Runs a study given as JSON text into the CSV file `out` (resuming it); the summary.");
}

/// cosserat.BatchStepper.
void BindBatchStepper(py::module_& m) {
  py::class_<PyBatchStepper>(m, "BatchStepper",
                             "M independent rods of the problem (a cantilever, SE(3) path) stepped "
                             "together on all cores, for controllers and learning loops: inputs "
                             "and outputs are (M, ...) NumPy arrays, and rod i reaches exactly "
                             "what a Stepper given the same inputs reaches.")
      .def(py::init<const io::Problem&, int, std::optional<int>>(), py::arg("problem"),
           py::arg("count"), py::arg("threads") = py::none(),
           "count rods of the problem on `threads` threads (default: all cores).")
      .def("initialize_at_rest", &PyBatchStepper::InitializeAtRest,
           "Every rod at rest under the problem's initial loads and actuation; returns how many "
           "converged.")
      .def("step", &PyBatchStepper::Step, py::arg("tip_force") = py::none(),
           py::arg("tension") = py::none(),
           "Advances every rod by dt: tip_force (M, 3) in N (world), tension (M, tendons) in N; "
           "what is not given keeps its last value (at first the problem's). Returns how many "
           "rods converged.")
      .def("tip_positions", &PyBatchStepper::TipPositions, "(M, 3) tip positions, m, world.")
      .def("positions", &PyBatchStepper::Positions, "(M, N, 3) node positions, m, world.")
      .def("save", &PyBatchStepper::Save,
           "A list of M Snapshots (each rod's run, as Stepper.save()) for restore(); allocates.")
      .def("restore", &PyBatchStepper::Restore, py::arg("snapshots"),
           "Rod i continues from snapshots[i] (a list of M), or every rod from one Snapshot (a "
           "Stepper's of the same problem: M rollouts from one measured state), each with the "
           "inputs its run was applying. A wrong count or a snapshot from another rod, grid or "
           "plan of steps raises ValueError and changes nothing.")
      .def("converged", &PyBatchStepper::Converged,
           "Whether each rod's last step converged (a list of M bools); a rod whose step failed "
           "keeps the last state it reached (times says where).")
      .def_property_readonly("times", &PyBatchStepper::Times, "Each rod's simulated time, s.")
      .def_property_readonly("time", &PyBatchStepper::time)
      .def_property_readonly("count", &PyBatchStepper::count);
}

}  // namespace

void BindBatches(py::module_& m) {
  BindBatchStepper(m);
  BindSweep(m);
}

}  // namespace cosserat::python
