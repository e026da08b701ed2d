// Second scenario for the Jacobian tracking of the peer release (issue 3): after 4 s of swing
// (2000 steps of 2 ms, Heun in s), a sideways tip kick: a force along +y equal to the preload
// (the weight of 0.02 kg) for one step. Prints the shot histogram of the 1000 steps from the
// kick on, and of the whole 6 s.
//
//   build/bench/kick_shots
#include <cstdio>

#include "cosserat/strong/bdf2_stepper.hpp"
#include "peer_rod.hpp"

int main() {
  using namespace cosserat;
  Bdf2Options opt;
  opt.dt = 2e-3;
  opt.spatial_scheme = SpatialScheme::kHeun;
  opt.tolerance = 1e-10;
  Bdf2ShootingStepper stepper(bench::PeerRod(), 40, opt);
  StepInput in = bench::PeerPreload();
  if (!stepper.InitializeAtRest(in).converged()) return 1;
  in.loads.tip_force.setZero();
  const int swing = 2000, after = 1000;
  long hist[2][6] = {}, shots[2] = {}, jac[2] = {};
  for (int i = 1; i <= swing + after; ++i) {
    StepInput now = in;
    if (i == swing + 1) now.loads.tip_force = Vec3(0, 0.02 * 9.81, 0);
    const StepSummary s = stepper.Step(now);
    if (!s.converged()) {
      std::printf("step %d failed\n", i);
      return 1;
    }
    const int bin = s.shots >= 5 ? 5 : s.shots;
    for (int w = 0; w < 2; ++w) {
      if (w == 1 && i <= swing) continue;
      ++hist[w][bin];
      shots[w] += s.shots;
      jac[w] += s.jacobians;
    }
  }
  const char* name[2] = {"whole run (3000)", "after kick (1000)"};
  const int n[2] = {swing + after, after};
  for (int w = 0; w < 2; ++w)
    std::printf("%-18s 1: %ld  2: %ld  3: %ld  4: %ld  >=5: %ld  shots/step %.4f  exact J %ld\n",
                name[w], hist[w][1], hist[w][2], hist[w][3], hist[w][4], hist[w][5],
                double(shots[w]) / n[w], jac[w]);
  return 0;
}
