// Workspace sweep of a tendon robot: 1 000 static solves at 41 grid points over a
// 40 × 25 grid of two tendon tensions, on 1 and on 2 threads.
//
// Run: build/bench/bench_sweep
#include <benchmark/benchmark.h>

#include "cosserat/analysis/sweep.hpp"

namespace {

using namespace cosserat;

// The backbone of robots/tendon_three_tendon.json with its two straight tendons.
RodModel Robot() {
  RodModel model = RodModel::Uniform(0.25, CrossSection::Circle(0.0004),
                                     Material::FromShearModulus(210e9, 80e9, 7800));
  model.tendons = {{"x", TendonRoute::Parallel(Vec2(0.008, 0))},
                   {"y", TendonRoute::Parallel(Vec2(0, 0.008))}};
  return model;
}

std::vector<Actuation> Grid() {
  std::vector<Actuation> points;
  for (int a = 0; a < 40; ++a)
    for (int b = 0; b < 25; ++b) {
      Actuation act;
      act.tendon_tension[0] = 3.0 * a / 39;
      act.tendon_tension[1] = 3.0 * (a % 2 ? 24 - b : b) / 24;  // serpentine
      points.push_back(act);
    }
  return points;
}

void BM_TendonWorkspace1000(benchmark::State& state) {
  const RodModel model = Robot();
  const std::vector<Actuation> points = Grid();
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  SweepOptions options;
  options.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const WorkspaceSweep w = SweepWorkspace(model, 41, {}, lie::SE3{}, loads, points, options);
    if (w.converged() != 1000) state.SkipWithError("a point did not converge");
    state.counters["wall_s"] = w.wall_time_s;
    state.counters["threads"] = w.threads;
  }
}

}  // namespace

BENCHMARK(BM_TendonWorkspace1000)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
