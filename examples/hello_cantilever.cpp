// The smallest useful program: a steel cantilever bent by its own weight and a tip load.
// Build and run:  cmake --build build --target hello_cantilever &&
// ./build/examples/hello_cantilever
#include <cstdio>

#include "cosserat/strong/static_shooting.hpp"

int main() {
  using namespace cosserat;

  // 0.5 m steel rod, circular section r = 1 mm, clamped at the origin pointing along +z.
  const RodModel rod = RodModel::Uniform(0.5, CrossSection::Circle(0.001),
                                         Material::FromShearModulus(200e9, 80e9, 8000));
  StaticShootingSolver solver(rod, /*num_nodes=*/41);

  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);  // gravity sideways, m/s²
  loads.tip_force = Vec3(-0.2, 0, 0);   // N, world frame (a dead load)

  const lie::SE3 base;  // identity: base at the origin, rod tangent = world z
  const StaticShootingSummary summary = solver.Solve(base, loads);
  if (!summary.converged()) {
    std::printf("did not converge: %s\n", ToString(summary.status));
    return 1;
  }

  const Vec3 tip = solver.state().tip_position_W();
  std::printf("converged in %d iterations (%d shots), residual %.1e, %.0f us\n", summary.iterations,
              summary.shots, summary.residual, summary.wall_time_s * 1e6);
  std::printf("tip position [m]: %.6f %.6f %.6f\n", tip.x(), tip.y(), tip.z());

  // A controller would now change the load and re-solve; the solver warm-starts.
  loads.tip_force *= 1.01;
  const StaticShootingSummary again = solver.Solve(base, loads);
  std::printf("re-solve after a 1 %% load change: %d shots, %.1f us\n", again.shots,
              again.wall_time_s * 1e6);
  return again.converged() ? 0 : 1;
}
