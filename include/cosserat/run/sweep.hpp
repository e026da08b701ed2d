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
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "cosserat/io/study.hpp"

namespace cosserat::run {

struct SweepOptions {
  int threads = 1;
  /// Called after each point with the points done and their total (a progress line); may be
  /// empty. Called from the worker threads, one at a time.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
  /// Asked after each point, one thread at a time; false stops the sweep after the points under
  /// way (their rows are kept, and a later run resumes). May be empty (run every point).
  std::function<bool()> keep_going;
  /// For tests: stop after this many new points (0: run them all).
  std::uint64_t max_new_points = 0;
};

struct SweepSummary {
  std::uint64_t points = 0;     ///< in the study
  std::uint64_t resumed = 0;    ///< already in the file
  std::uint64_t ran = 0;        ///< run now
  std::uint64_t failed = 0;     ///< rows whose status is not "converged"
  /// Lines of a resumed file that are no rows of this study (no index below its point count in
  /// front, or a point's second row: the last one is kept), dropped; a torn last line, which a
  /// killed run leaves, is not counted.
  std::uint64_t dropped = 0;
  bool complete = false;        ///< every point has its row (and the file is in point order)
  double wall_time_s = 0.0;
  /// Outputs ("name" (pointer)) empty in every converged row, when some row converged: a pointer
  /// that names nothing in the result (a typo such as /tip/positoin/0) fills a blank column.
  std::vector<std::string> empty_outputs;
};

/// Runs the study into `csv_path` (created, or resumed). Throws std::runtime_error when the file
/// cannot be written or belongs to another study (its header differs).
SweepSummary RunSweep(const io::Study& study, const std::string& csv_path,
                      const SweepOptions& options = {});

/// Point k of the study run: its CSV row, without the line break.
std::string SweepPointRow(const io::Study& study, std::uint64_t k);

/// A study's results file, for runners that hand out points themselves (RunSweep's threads, MPI
/// ranks): opening it resumes (keeps the whole rows of this study, drops a torn last line),
/// Append writes one row in one write, Finish rewrites it in point order once every point has its
/// row. Append may be called from several threads.
class SweepFile {
 public:
  /// Throws std::runtime_error as RunSweep does.
  SweepFile(const io::Study& study, const std::string& path);
  ~SweepFile();
  SweepFile(const SweepFile&) = delete;
  SweepFile& operator=(const SweepFile&) = delete;

  /// The points without a row, in order.
  const std::vector<std::uint64_t>& pending() const { return pending_; }
  std::uint64_t resumed() const { return resumed_; }
  /// Writes point k's row (without its line break); returns the rows in the file.
  std::uint64_t Append(std::uint64_t k, const std::string& row);
  /// Rewrites the file in point order if every point has its row; the summary's counts.
  SweepSummary Finish();

 private:
  std::string path_, header_;
  std::uint64_t points_ = 0, resumed_ = 0, ran_ = 0;
  std::size_t status_column_ = 0;
  std::vector<std::string> outputs_;  ///< "name" (pointer) of each output column, in order
  std::map<std::uint64_t, std::string> rows_;
  std::vector<std::uint64_t> pending_;
  std::uint64_t dropped_ = 0;
  /// A file descriptor closed with its owner, also when the constructor throws (closing it
  /// releases a lock held on it).
  struct OwnedFd {
    int fd = -1;
    ~OwnedFd();
  };
  OwnedFd lock_;  ///< `<csv>.lock`, flock'ed while this object lives
  int fd_ = -1;
  bool write_failed_ = false;
  std::mutex mutex_;
};

/// The CSV header of the study's rows.
std::string SweepHeader(const io::Study& study);

}  // namespace cosserat::run
