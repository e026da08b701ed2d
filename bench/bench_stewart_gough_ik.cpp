// Inverse kinematics of the continuum Stewart–Gough robot at a controller's rate: the loop of
// Till, Aloi & Rucker's benchmark (their 01_Statics/03_CSG_IK_Speedup example). From the
// platform at (0, 0.02, 0.48) m, 50 000 solves, each warm-started from the last, the platform
// moving 1 mm in y and z per solve, up for 100 solves and down for 100. Prints the CPU time and
// the rate, as their program does, and the worst residual and the iterations per solve.
//
//   build/bench/bench_stewart_gough_ik [--tolerance 1e-10] [--solves 50000]
//
// Their stop is a sum of squares of their residual (m, rad, N, N·m) of 1e-6, i.e. a norm of 1e-3;
// ours is the norm of the residual scaled by the rod's length, EI/L and EI/L² (0.4 m, 0.072 N·m,
// 0.18 N): --tolerance 2.5e-3 matches theirs in position (1 mm) and is 5 times tighter in force.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "cosserat/assembly/assembly_statics.hpp"
#include "cosserat/robots/stewart_gough.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  AssemblyOptions options;
  int solves = 50000;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--tolerance")) options.tolerance = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--solves")) solves = std::atoi(argv[i + 1]);
  }
  AssemblyStaticsSolver solver(ContinuumStewartGough(), options);
  const StaticLoads none;
  lie::SE3 pose;
  pose.p = Vec3(0, 0, 0.4);
  if (!solver.SolveLengths(none, {pose}).converged()) return 1;
  pose.p = Vec3(0, 0.02, 0.48);
  if (!solver.SolveLengths(none, {pose}).converged()) return 1;
  double worst = 0.0;
  long iterations = 0, jacobians = 0;
  int failed = 0;
  const std::clock_t start = std::clock();
  for (int i = 0; i < solves; ++i) {
    const double step = i % 200 < 100 ? 0.001 : -0.001;
    pose.p.y() += step;
    pose.p.z() += step;
    const AssemblySummary s = solver.SolveLengths(none, {pose});
    if (!s.converged()) ++failed;
    worst = std::max(worst, s.residual);
    iterations += s.iterations;
    jacobians += s.jacobians;
  }
  const double seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
  std::printf("Time elapsed: %.4f s\nSolution rate: %.1f Hz\n", seconds, solves / seconds);
  std::printf("tolerance %.1e: worst residual %.2e, %.2f iterations and %.3f Jacobians per "
              "solve, %d failed\n",
              options.tolerance, worst, double(iterations) / solves, double(jacobians) / solves,
              failed);
  return failed == 0 ? 0 : 1;
}
