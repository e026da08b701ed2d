// One static solve of a 0.5 m steel cantilever (r = 1 mm, E = 200 GPa, G = 80 GPa) under a
// 0.5 N tip load perpendicular to the rod (PL²/EI ≈ 0.8, tip deflection ≈ 0.25 L), at N = 41,
// 101 and 401 grid points.
//   Cold: a new solver each time, no previous solution (includes the construction).
//   Warm: the load alternates by 1 % between calls, so each Solve() is a re-solve after a 1 %
//         change, warm-started from the previous solution.
// Run: build/bench/bench_static --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include "cosserat/strong/static_shooting.hpp"

namespace {

using namespace cosserat;

RodModel SteelRod() {
  return RodModel::Uniform(0.5, CrossSection::Circle(0.001),
                           Material::FromShearModulus(200e9, 80e9, 8000));
}

StaticLoads TipLoad(double P) {
  StaticLoads loads;
  loads.tip_force = Vec3(-P, 0, 0);
  return loads;
}

void BM_StaticSolveCold(benchmark::State& state) {
  const RodModel model = SteelRod();
  const int nodes = static_cast<int>(state.range(0));
  const StaticLoads loads = TipLoad(0.5);
  for (auto _ : state) {
    StaticShootingSolver solver(model, nodes);
    const auto summary = solver.Solve(lie::SE3{}, loads);
    if (!summary.converged()) state.SkipWithError("did not converge");
    benchmark::DoNotOptimize(solver.state().tip_position_W());
  }
}

void BM_StaticSolveColdNoSetup(benchmark::State& state) {
  const int nodes = static_cast<int>(state.range(0));
  StaticShootingSolver solver(SteelRod(), nodes);
  const StaticLoads loads = TipLoad(0.5);
  for (auto _ : state) {
    solver.ResetWarmStart();
    const auto summary = solver.Solve(lie::SE3{}, loads);
    if (!summary.converged()) state.SkipWithError("did not converge");
    benchmark::DoNotOptimize(solver.state().tip_position_W());
  }
}

void BM_StaticResolveWarm1Percent(benchmark::State& state) {
  const int nodes = static_cast<int>(state.range(0));
  StaticShootingSolver solver(SteelRod(), nodes);
  const StaticLoads a = TipLoad(0.5), b = TipLoad(0.505);
  if (!solver.Solve(lie::SE3{}, a).converged()) state.SkipWithError("did not converge");
  bool flip = false;
  int shots = 0, solves = 0;
  for (auto _ : state) {
    flip = !flip;
    const auto summary = solver.Solve(lie::SE3{}, flip ? b : a);
    if (!summary.converged()) state.SkipWithError("did not converge");
    shots += summary.shots;
    ++solves;
    benchmark::DoNotOptimize(solver.state().tip_position_W());
  }
  state.counters["shots_per_solve"] = static_cast<double>(shots) / std::max(solves, 1);
}

}  // namespace

BENCHMARK(BM_StaticSolveCold)->Arg(41)->Arg(101)->Arg(401)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticSolveColdNoSetup)->Arg(41)->Arg(101)->Arg(401)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticResolveWarm1Percent)->Arg(41)->Arg(101)->Arg(401)->Unit(benchmark::kMicrosecond);
