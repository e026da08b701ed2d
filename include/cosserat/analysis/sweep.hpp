#pragma once
/// \file
/// Parameter sweeps on all cores: many independent static solves (workspace of a robot over its
/// actuation, or a design parameter), split into contiguous chunks, one solver per thread (the
/// Model/Data split: models are shared read-only, every thread owns its workspace).

#include <functional>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/solve_status.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

struct SweepOptions {
  int threads = 0;  ///< 0: all hardware threads
};

/// Calls fn(index, thread) for index = 0 … count − 1 on `threads` threads (0: all), each thread
/// taking one contiguous chunk in order, so a thread can warm-start each item from the previous
/// one. Returns the number of threads used. Exceptions in fn are rethrown after all threads end.
int ParallelFor(int count, int threads, const std::function<void(int index, int thread)>& fn);

struct WorkspaceSweep {
  std::vector<Vec3> tip_position_W;  ///< m, one per actuation point
  std::vector<Mat3> tip_rotation_WB;
  std::vector<SolveStatus> status;
  int threads = 0;
  double wall_time_s = 0.0;
  int converged() const;
};

/// The robot's tip over a list of actuation states (tendon tensions, pressures, jamming states):
/// one static solve each, in parallel, each thread warm-starting along its chunk (order the
/// points so neighbours are close, e.g. a serpentine over a grid).
WorkspaceSweep SweepWorkspace(const RodModel& model, int nodes, const StaticShootingOptions& solver,
                              const lie::SE3& base, const StaticLoads& loads,
                              const std::vector<Actuation>& points,
                              const SweepOptions& options = {});

}  // namespace cosserat
