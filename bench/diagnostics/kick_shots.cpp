// Second scenario for the Jacobian tracking of the peer release (bench/peer_rod.hpp): after 4 s of swing
// (2000 steps of 2 ms, Heun in s), a sideways tip kick: a force along +y equal to the preload
// (the weight of 0.02 kg) for one step. Prints the shot histogram of the 1000 steps from the
// kick on, and of the whole 6 s.
//
//   build/bench/diagnostics/kick_shots
#include <cstdio>

#include "cosserat/strong/bdf2_stepper.hpp"
#include "../peer_rod.hpp"
#include "shot_histogram.hpp"

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
  bench::ShotHistogram whole, kicked;
  for (int i = 1; i <= swing + after; ++i) {
    StepInput now = in;
    if (i == swing + 1) now.loads.tip_force = Vec3(0, 0.02 * 9.81, 0);
    const StepSummary s = stepper.Step(now);
    if (!s.converged()) {
      std::printf("step %d failed\n", i);
      return 1;
    }
    whole.Add(s);
    if (i > swing) kicked.Add(s);
  }
  whole.Print("whole run (3000)");
  kicked.Print("after kick (1000)");
  return 0;
}
