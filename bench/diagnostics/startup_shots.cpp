// Shot histogram of the peer release (bench/peer_rod.hpp; Heun in s, dt = 2 ms, 25 s): how many steps take
// 2, 3, 4 and >= 5 shots, over the whole run and in the first 0.2 s after the release, and the
// shots per step. With an argument n > 0 it also prints the first n steps (shots, exact
// Jacobians, Newton iterations); a second argument `rk4` runs RK4 in s instead of Heun.
//
//   build/bench/diagnostics/startup_shots [n [rk4]]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cosserat/strong/bdf2_stepper.hpp"
#include "../peer_rod.hpp"
#include "shot_histogram.hpp"

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
  bench::ShotHistogram whole, first;
  for (int i = 1; i <= steps; ++i) {
    const StepSummary s = stepper.Step(in);
    if (!s.converged()) {
      std::printf("step %d failed\n", i);
      return 1;
    }
    whole.Add(s);
    if (i <= startup) first.Add(s);
    if (i <= print)
      std::printf("step %3d  shots %2d  jacobians %d  iterations %2d\n", i, s.shots, s.jacobians,
                  s.iterations);
  }
  whole.Print("whole run (12500)");
  first.Print("first 0.2 s (100)");
  return 0;
}
