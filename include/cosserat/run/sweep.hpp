#pragma once
/// \file
/// Runs a study (io/study.hpp) point by point, on threads that take the next point as they
/// finish one (points differ in cost), writing one CSV row per point as it finishes: index, the
/// parameters (by path), the outputs (by name), status, wall_time_s. A row is written whole with
/// its newline, so a study killed at any moment leaves only whole rows (a torn last line is
/// dropped when it resumes); restarted on the same file, it runs only the points without a row.
/// When every point has its row, the file is rewritten in point order: studies run with any
/// number of threads give identical files apart from the timing column.

#include <cstdint>
#include <functional>
#include <string>

#include "cosserat/io/study.hpp"

namespace cosserat::run {

struct SweepOptions {
  int threads = 1;
  /// Called after each point with the points done and their total (a progress line); may be
  /// empty. Called from the worker threads, one at a time.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
  /// For tests: stop after this many new points (0: run them all).
  std::uint64_t max_new_points = 0;
};

struct SweepSummary {
  std::uint64_t points = 0;     ///< in the study
  std::uint64_t resumed = 0;    ///< already in the file
  std::uint64_t ran = 0;        ///< run now
  std::uint64_t failed = 0;     ///< rows whose status is not "converged"
  bool complete = false;        ///< every point has its row (and the file is in point order)
  double wall_time_s = 0.0;
};

/// Runs the study into `csv_path` (created, or resumed). Throws std::runtime_error when the file
/// cannot be written or belongs to another study (its header differs).
SweepSummary RunSweep(const io::Study& study, const std::string& csv_path,
                      const SweepOptions& options = {});

/// The CSV header of the study's rows.
std::string SweepHeader(const io::Study& study);

}  // namespace cosserat::run
