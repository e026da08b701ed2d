#include "sweep_mpi.hpp"

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#ifdef COSSERAT_HAVE_MPI
#include <mpi.h>
#endif

namespace cosserat::apps {

namespace {

/// Whether an MPI launcher gave this process a rank: mpirun (OpenMPI, MPICH) or srun's PMI or
/// PMIx plugin, which exports PMIX_RANK but no size.
bool HasLaunchedRank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace

int LaunchedRanks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  if (HasLaunchedRank())  // srun --mpi=pmix: the step's task count
    for (const char* name : {"SLURM_STEP_NUM_TASKS", "SLURM_NTASKS"})
      if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return 1;
}

int LaunchedRank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* v = std::getenv(name)) return std::max(0, std::atoi(v));
  return 0;
}

bool UnjoinedSlurmTasks(int* tasks) {
  const char* ntasks = std::getenv("SLURM_NTASKS");
  *tasks = ntasks ? std::atoi(ntasks) : 1;
  return *tasks > 1 && std::getenv("SLURM_STEP_ID") && !HasLaunchedRank();
}

#ifndef COSSERAT_HAVE_MPI

bool HaveMpi() { return false; }

run::SweepSummary RunSweepMpi(const io::Study&, const std::string&, int,
                              const std::function<void(std::uint64_t, std::uint64_t)>&, bool*,
                              int*) {
  throw std::runtime_error("this build has no MPI (install libopenmpi-dev and build again)");
}

#else

namespace {

constexpr int kTagRequest = 1;  // worker -> root: a flag ('1' more, '0' last) and rows
constexpr int kTagPoint = 2;    // root -> worker: up to kChunk point indices; none: no more
// Points per request: a worker asks for its next chunk before computing the one in hand, so the
// root's answer (after the point the root is computing, or 1 ms of its idle wait) comes while it
// computes 16 points (~1 ms each); the chunks stay small against a study for the balance at the
// end.
constexpr int kChunk = 16;

/// A rank other than 0. Its messages to the root are a flag and the rows of its last chunk
/// ("k\trow" lines): flag '1' asks for a chunk, '0' is its last message. It asks for the next
/// chunk before computing the one in hand, so the root's answer arrives while it computes.
void ComputeForRoot(const io::Study& study) {
  auto send = [](const std::string& message) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kTagRequest,
             MPI_COMM_WORLD);
  };
  std::vector<std::int64_t> chunk(kChunk);
  auto receive = [&] {
    MPI_Status status;
    MPI_Recv(chunk.data(), kChunk, MPI_INT64_T, 0, kTagPoint, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_INT64_T, &count);
    return count;
  };
  std::string rows;
  send("1");
  for (int count = receive(); count > 0;) {
    const std::vector<std::int64_t> in_hand(chunk.begin(), chunk.begin() + count);
    send("1" + rows);
    rows.clear();
    for (std::int64_t k : in_hand)
      rows += std::to_string(k) + "\t" + run::SweepPointRow(study, static_cast<std::uint64_t>(k)) +
              "\n";
    count = receive();
  }
  send("0" + rows);
}

/// Rank 0's main thread: takes the rows the other `workers` ranks send and hands each the next
/// chunk of `pending` from the counter the root's own threads share, computing points itself
/// between requests, until every rank got none and no point is left.
template <typename Report>
void ServeRanks(int workers, const io::Study& study, const std::vector<std::uint64_t>& pending,
                std::atomic<std::size_t>* next_index, run::SweepFile* file_out,
                const Report& report) {
  std::atomic<std::size_t>& next = *next_index;
  run::SweepFile& file = *file_out;
  int active = workers;
  std::vector<char> buffer;
  bool local_work = true;
  while (active > 0 || local_work) {
    int flag = 0;
    MPI_Status status;
    if (active > 0) MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &flag, &status);
    if (!flag) {
      // Nobody asks: compute a point here (a request then waits at most one point), or wait.
      const std::size_t i = local_work ? next++ : pending.size();
      if (i < pending.size())
        report(file.Append(pending[i], run::SweepPointRow(study, pending[i])));
      else if ((local_work = false), active > 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    int count = 0;
    MPI_Get_count(&status, MPI_CHAR, &count);
    buffer.resize(static_cast<std::size_t>(count));
    MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    const std::string message(buffer.begin(), buffer.end());
    for (std::size_t start = 1; start < message.size();) {
      const std::size_t tab = message.find('\t', start), end = message.find('\n', start);
      report(file.Append(std::stoull(message.substr(start, tab - start)),
                         message.substr(tab + 1, end - tab - 1)));
      start = end + 1;
    }
    if (message.empty() || message[0] != '1') {  // the rank's last message
      --active;
      continue;
    }
    std::int64_t chunk[kChunk];
    int handed = 0;
    for (std::size_t i; handed < kChunk && (i = next++) < pending.size();)
      chunk[handed++] = static_cast<std::int64_t>(pending[i]);
    MPI_Send(chunk, handed, MPI_INT64_T, status.MPI_SOURCE, kTagPoint, MPI_COMM_WORLD);
  }
}

}  // namespace

bool HaveMpi() { return true; }

run::SweepSummary RunSweepMpi(const io::Study& study, const std::string& path, int threads,
                              const std::function<void(std::uint64_t, std::uint64_t)>& progress,
                              bool* is_root, int* ranks) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  *is_root = rank == 0;
  *ranks = size;
  run::SweepSummary summary;
  if (rank != 0) {
    ComputeForRoot(study);
    MPI_Finalize();
    return summary;
  }
  const auto t0 = std::chrono::steady_clock::now();
  run::SweepFile file(study, path);
  const std::vector<std::uint64_t>& pending = file.pending();
  const std::uint64_t total = study.PointCount();
  std::atomic<std::size_t> next{0};
  std::mutex progress_mutex;
  auto report = [&](std::uint64_t done) {
    if (!progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    progress(done, total);
  };
  // The root's own extra threads take points from the same counter as the other ranks.
  std::vector<std::thread> local;
  for (int t = 1; t < threads; ++t)
    local.emplace_back([&] {
      for (std::size_t i = next++; i < pending.size(); i = next++)
        report(file.Append(pending[i], run::SweepPointRow(study, pending[i])));
    });
  // The root's main thread serves the other ranks (MPI from this thread only).
  ServeRanks(size - 1, study, pending, &next, &file, report);
  for (std::thread& t : local) t.join();
  summary = file.Finish();
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MPI_Finalize();
  return summary;
}

#endif

}  // namespace cosserat::apps
