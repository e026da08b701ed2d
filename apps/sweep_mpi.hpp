#pragma once
// `mpirun -np K cosserat sweep STUDY.json --out RESULTS.csv`: the study's points spread over K
// MPI ranks (sweep_mpi.cpp, built when CMake finds MPI).

#include <cstdint>
#include <functional>
#include <string>

#include "cosserat/io/study.hpp"
#include "cosserat/run/sweep.hpp"

namespace cosserat::apps {

/// The number of ranks this process was started with by mpirun (OpenMPI's, MPICH's or PMI's
/// size), or by srun with a PMIx rank (the step's SLURM task count), or 1.
int LaunchedRanks();

/// This process's rank among them (the same environments), or 0.
int LaunchedRank();

/// True when this build can run a sweep over MPI ranks.
bool HaveMpi();

/// Whether SLURM started this process as one of several tasks of a step (srun: SLURM_NTASKS
/// above 1 with a SLURM_STEP_ID) that no MPI environment joins (no OpenMPI, PMI or PMIx rank):
/// every task would run the whole study. *tasks receives SLURM_NTASKS.
bool UnjoinedSlurmTasks(int* tasks);

/// Runs the study over MPI: rank 0 owns the file and hands out points, a chunk at a time, to
/// whichever rank asks (points differ in cost), and computes points between requests, and on
/// `threads` − 1 more threads of its own; the other ranks compute one point at a time. Every
/// rank returns; rank 0's summary counts the study, the others' are empty. `is_root` says
/// which, and *ranks receives the number of ranks MPI joined (not the environment's claim).
run::SweepSummary RunSweepMpi(const io::Study& study, const std::string& path, int threads,
                              const std::function<void(std::uint64_t, std::uint64_t)>& progress,
                              bool* is_root, int* ranks);

}  // namespace cosserat::apps
