#include "cosserat/analysis/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

namespace cosserat {

int ParallelFor(int count, int threads, const std::function<void(int, int)>& fn) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, count));
  std::exception_ptr error;
  std::mutex error_mutex;
  auto chunk = [&](int t) {
    const int begin = static_cast<int>(static_cast<long>(count) * t / threads);
    const int end = static_cast<int>(static_cast<long>(count) * (t + 1) / threads);
    try {
      for (int i = begin; i < end; ++i) fn(i, t);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(chunk, t);
  chunk(0);  // this thread takes the first chunk
  for (std::thread& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  return threads;
}

int WorkspaceSweep::converged() const {
  return static_cast<int>(std::count(status.begin(), status.end(), SolveStatus::kConverged));
}

WorkspaceSweep SweepWorkspace(const RodModel& model, int nodes, const StaticShootingOptions& solver,
                              const lie::SE3& base, const StaticLoads& loads,
                              const std::vector<Actuation>& points, const SweepOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const int count = static_cast<int>(points.size());
  WorkspaceSweep out;
  out.tip_position_W.assign(count, Vec3::Constant(NAN));
  out.tip_rotation_WB.assign(count, Mat3::Constant(NAN));
  out.status.assign(count, SolveStatus::kNotRun);
  if (count == 0) return out;
  int threads = options.threads;
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, count));
  // One solver per thread, built here (construction allocates; the solves then reuse it).
  std::vector<std::unique_ptr<StaticShootingSolver>> solvers;
  for (int t = 0; t < threads; ++t)
    solvers.push_back(std::make_unique<StaticShootingSolver>(model, nodes, solver, points[0]));
  out.threads = ParallelFor(count, threads, [&](int i, int t) {
    StaticShootingSolver& s = *solvers[t];
    s.SetActuation(points[i]);
    const StaticShootingSummary summary = s.Solve(base, loads);
    out.status[i] = summary.status;
    if (summary.converged()) {
      out.tip_position_W[i] = s.state().tip_position_W();
      out.tip_rotation_WB[i] = s.state().tip_rotation_WB();
    }
  });
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cosserat
