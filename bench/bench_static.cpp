// One static solve of a 0.5 m steel cantilever (r = 1 mm, E = 200 GPa, G = 80 GPa) under a
// 0.5 N tip load perpendicular to the rod (PL²/EI ≈ 0.8, tip deflection ≈ 0.25 L), at N = 41,
// 101 and 401 grid points.
//   Cold: a new solver each time, no previous solution (includes the construction).
//   Warm: the load alternates by 1 % between calls, so each Solve() is a re-solve after a 1 %
//         change, warm-started from the previous solution.
//   Tendons: the backbone of robots/tendon_three_tendon.json's kind (spring steel, r = 0.4 mm,
//         0.25 m, gravity across it) with 2 or 4 parallel tendons 8 mm out, the first one's
//         tension alternating between 1 and 1.01 N; and its tip Jacobian in the tensions.
// Run: build/bench/bench_static --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

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

RodModel TendonBackbone(int tendons) {
  RodModel rod = RodModel::Uniform(0.25, CrossSection::Circle(0.0004),
                                   Material::FromShearModulus(210e9, 80e9, 7800));
  for (int i = 0; i < tendons; ++i) {
    const double angle = 2.0 * M_PI * i / tendons;
    rod.tendons.push_back(
        {"t" + std::to_string(i),
         TendonRoute::Parallel(0.008 * Vec2(std::cos(angle), std::sin(angle)))});
  }
  return rod;
}

void BM_TendonResolveWarm1Percent(benchmark::State& state) {
  StaticShootingSolver solver(TendonBackbone(static_cast<int>(state.range(0))), 41);
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);
  Actuation a, b;
  a.tendon_tension[0] = 1.0;
  b.tendon_tension[0] = 1.01;
  solver.SetActuation(a);
  if (!solver.Solve(lie::SE3{}, loads).converged()) state.SkipWithError("did not converge");
  bool flip = false;
  for (auto _ : state) {
    flip = !flip;
    solver.SetActuation(flip ? b : a);
    if (!solver.Solve(lie::SE3{}, loads).converged()) state.SkipWithError("did not converge");
    benchmark::DoNotOptimize(solver.state().tip_position_W());
  }
}

void BM_TendonTipJacobian(benchmark::State& state) {
  StaticShootingSolver solver(TendonBackbone(static_cast<int>(state.range(0))), 41);
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81, 0, 0);
  Actuation a;
  a.tendon_tension[0] = 1.0;
  solver.SetActuation(a);
  if (!solver.Solve(lie::SE3{}, loads).converged()) state.SkipWithError("did not converge");
  StaticShootingSolver::TensionJacobian J;
  for (auto _ : state) {
    if (!solver.TipJacobianWrtTensions(lie::SE3{}, loads, &J)) state.SkipWithError("failed");
    benchmark::DoNotOptimize(J);
  }
}

}  // namespace

BENCHMARK(BM_TendonResolveWarm1Percent)->Arg(2)->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TendonTipJacobian)->Arg(2)->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticSolveCold)->Arg(41)->Arg(101)->Arg(401)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticSolveColdNoSetup)->Arg(41)->Arg(101)->Arg(401)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticResolveWarm1Percent)->Arg(41)->Arg(101)->Arg(401)->Unit(benchmark::kMicrosecond);
