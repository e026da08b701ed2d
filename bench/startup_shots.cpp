// Shot histogram of the peer release (issue 3, Heun in s, dt = 2 ms, 25 s): how many steps take
// 2, 3, 4 and >= 5 shots, over the whole run and in the first 0.2 s after the release, and the
// shots per step. With an argument n > 0 it also prints the first n steps (shots, exact
// Jacobians, Newton iterations); a second argument `rk4` runs RK4 in s instead of Heun.
//
//   build/bench/startup_shots [n [rk4]]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cosserat/strong/bdf2_stepper.hpp"
#include "peer_rod.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  const int print = argc > 1 ? std::atoi(argv[1]) : 0;
  Bdf2Options opt;
  opt.dt = 2e-3;
  opt.spatial_scheme =
      argc > 2 && std::string(argv[2]) == "rk4" ? SpatialScheme::kRk4 : SpatialScheme::kHeun;
  opt.tolerance = 1e-10;
  Bdf2ShootingStepper stepper(bench::PeerRod(), 40, opt);
  StepInput in = bench::PeerPreload();
  if (!stepper.InitializeAtRest(in).converged()) return 1;
  in.loads.tip_force.setZero();
  const int steps = 12500, startup = 100;  // 0.2 s
  long hist[2][6] = {}, shots[2] = {}, jac[2] = {};
  for (int i = 1; i <= steps; ++i) {
    const StepSummary s = stepper.Step(in);
    if (!s.converged()) {
      std::printf("step %d failed\n", i);
      return 1;
    }
    const int bin = s.shots >= 5 ? 5 : s.shots;
    for (int w = 0; w < 2; ++w) {
      if (w == 1 && i > startup) continue;
      ++hist[w][bin];
      shots[w] += s.shots;
      jac[w] += s.jacobians;
    }
    if (i <= print)
      std::printf("step %3d  shots %2d  jacobians %d  iterations %2d\n", i, s.shots, s.jacobians,
                  s.iterations);
  }
  const char* name[2] = {"whole run (12500)", "first 0.2 s (100)"};
  for (int w = 0; w < 2; ++w)
    std::printf("%-18s 1: %ld  2: %ld  3: %ld  4: %ld  >=5: %ld  shots/step %.4f  exact J %ld\n",
                name[w], hist[w][1], hist[w][2], hist[w][3], hist[w][4], hist[w][5],
                double(shots[w]) / (w ? startup : steps), jac[w]);
  return 0;
}
