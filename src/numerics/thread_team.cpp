#include "cosserat/numerics/thread_team.hpp"

#include <algorithm>
#include <system_error>
#include <utility>

namespace cosserat {

ThreadTeam::ThreadTeam(int threads) {
  for (int t = 1; t < std::max(1, threads); ++t) {
    try {
      workers_.emplace_back([this] { Work(); });
    } catch (const std::system_error&) {
      break;  // the system has no more threads to give: a smaller team does the same work
    }
  }
}

ThreadTeam::~ThreadTeam() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void ThreadTeam::Drain() {
  for (std::size_t i = next_++; i < n_; i = next_++) {
    try {
      job_(context_, i);
    } catch (...) {  // kept for the caller: an exception must not leave a worker thread
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
}

void ThreadTeam::Work() {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    Drain();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }
}

void ThreadTeam::Run(std::size_t n, void (*job)(void*, std::size_t), void* context) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    n_ = n;
    job_ = job;
    context_ = context;
    next_ = 0;
    busy_ = workers_.size();
    ++generation_;
  }
  wake_.notify_all();
  Drain();
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

}  // namespace cosserat
