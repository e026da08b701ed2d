#pragma once
/// \file
/// A fixed team of threads that runs one job over the indices [0, n) per call, the calling
/// thread taking part: each thread takes the next index as it finishes one. Built once; a call
/// allocates nothing (the job is passed as a function pointer and a context, not a
/// std::function), so a controller can run it every tick.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace cosserat {

class ThreadTeam {
 public:
  /// `threads` in all, the caller included (at least 1); fewer when the system cannot start
  /// that many (size() says how many).
  explicit ThreadTeam(int threads);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  /// Runs job(context, i) for every i in [0, n) and returns when all are done. An exception a
  /// job throws (on any thread) is rethrown here once all are done, the first one if several.
  void Run(std::size_t n, void (*job)(void* context, std::size_t i), void* context);

  /// The same for a callable `f(i)`, without allocating.
  template <typename F>
  void For(std::size_t n, F& f) {
    Run(n, [](void* c, std::size_t i) { (*static_cast<F*>(c))(i); }, &f);
  }

  int size() const { return static_cast<int>(workers_.size()) + 1; }

 private:
  void Work();
  void Drain();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::size_t generation_ = 0;  ///< counts the calls; a worker runs each once
  std::size_t busy_ = 0;        ///< workers still in the current call
  bool stop_ = false;
  // The current call.
  std::size_t n_ = 0;
  void (*job_)(void*, std::size_t) = nullptr;
  void* context_ = nullptr;
  std::atomic<std::size_t> next_{0};
  std::exception_ptr error_;  ///< the first exception a job of the current call threw
};

}  // namespace cosserat
