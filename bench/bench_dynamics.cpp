// The peer problem (also examples/cantilever_release.json): a steel cantilever
// (E 200 GPa, G 80 GPa, ρ 8000 kg/m³, r = 1 mm, L = 0.5 m, 40 grid points, no damping), clamped
// along +z, gravity 9.81 m/s² along −x, held in equilibrium under an extra tip force equal to
// the weight of 0.02 kg and released at t = 0; dt = 2 ms for 25 s.
//
//   BM_PeerRelease: the whole run through Step(), one Step() timed at a time. Counters: the
//     real-time ratio (simulated / wall), per-step median, p99 and max (µs), shots per step, and
//     the steps that took 3 and >= 4 shots (the p99 is a >= 4-shot step while there are more
//     than 1 % of them). BM_PeerRelease*FastestOf5: each step's fastest time of 5 passes.
//   BM_PeerAccuracy*: the tip trajectory against a reference run with a finer grid or step;
//     counters: the largest tip distance over the run, in mm and as a fraction of L.
//
// Run: build/bench/bench_dynamics --benchmark_filter=Peer
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "cosserat/strong/bdf2_stepper.hpp"
#include "peer_rod.hpp"

namespace {

using namespace cosserat;
using bench::PeerPreload;
using bench::PeerRod;

constexpr double kLength = 0.5, kDuration = 25.0;

struct Run {
  std::vector<Vec3> tip;  // every `record_every` steps
  std::vector<double> step_us;
  long shots = 0;
  long steps_3_shots = 0, steps_4_or_more = 0;  // the tail that sets the p99 (BENCHMARKS.md)
  bool ok = true;
};

Run Simulate(int nodes, double dt, int record_every, double tolerance, int pieces = 1,
             SpatialScheme scheme = SpatialScheme::kRk4) {
  Bdf2Options opt;
  opt.dt = dt;
  opt.spatial_scheme = scheme;
  opt.shooting_segments = pieces;
  opt.tolerance = tolerance;
  Bdf2ShootingStepper stepper(PeerRod(), nodes, opt);
  StepInput in = PeerPreload();
  Run run;
  run.ok = stepper.InitializeAtRest(in).converged();
  in.loads.tip_force.setZero();  // released
  const int steps = static_cast<int>(std::lround(kDuration / dt));
  run.step_us.reserve(steps);
  run.tip.push_back(stepper.state().tip_position_W());
  for (int i = 1; i <= steps && run.ok; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const StepSummary s = stepper.Step(in);
    run.step_us.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    run.shots += s.shots;
    run.steps_3_shots += s.shots == 3;
    run.steps_4_or_more += s.shots >= 4;
    run.ok = s.converged();
    if (i % record_every == 0) run.tip.push_back(stepper.state().tip_position_W());
  }
  return run;
}

// passes > 1: the run is repeated (it is deterministic: the same shots in every step) and each
// step's time is its fastest over the passes, which removes what the machine adds (interrupts,
// another tenant) and leaves what the step's own work costs.
void PeerRelease(benchmark::State& state, SpatialScheme scheme, int passes = 1) {
  for (auto _ : state) {
    Run run = Simulate(40, 2e-3, 1, 1e-10, 1, scheme);
    for (int k = 1; k < passes && run.ok; ++k) {
      const Run again = Simulate(40, 2e-3, 1, 1e-10, 1, scheme);
      run.ok = again.ok && again.step_us.size() == run.step_us.size();
      for (size_t i = 0; run.ok && i < run.step_us.size(); ++i)
        run.step_us[i] = std::min(run.step_us[i], again.step_us[i]);
    }
    if (!run.ok) state.SkipWithError("a step failed");
    std::vector<double> t = run.step_us;
    std::sort(t.begin(), t.end());
    double total = 0;
    for (double v : t) total += v;
    const double median = t[t.size() / 2], p99 = t[static_cast<size_t>(0.99 * (t.size() - 1))];
    state.counters["real_time_ratio"] = kDuration / (total * 1e-6);
    state.counters["median_us"] = median;
    state.counters["p99_us"] = p99;
    state.counters["p99_over_median"] = p99 / median;
    state.counters["max_us"] = t.back();
    state.counters["shots_per_step"] = static_cast<double>(run.shots) / t.size();
    state.counters["steps_3_shots"] = run.steps_3_shots;
    state.counters["steps_4plus_shots"] = run.steps_4_or_more;
  }
}

// The tip trajectory against a reference with 4× the grid points (same dt), with 4× the grid
// and dt/2, and with 4× the grid and dt/8 (the fine reference). Single shooting cannot take
// dt/8 on this problem: the shot's bending exponent λL ≈ sqrt(5.3/(ω1 dt)) reaches 17 at
// dt = 0.5 ms and 24 at 0.25 ms, and Newton diverges in the first steps after release; the dt/8
// reference therefore shoots in 8 pieces (Bdf2Options::shooting_segments, same discrete
// equations, e^3 per piece).
// Runs the peer problem and a reference; compares the tips at common times: every
// `every_run`-th frame of the run against every `every_ref`-th frame of the reference.
// Counters: the largest tip distance over the 25 s, and over the first 1 s and 5 s (BDF2's
// phase error grows with time).
void CompareTo(benchmark::State& state, int ref_nodes, double ref_dt, int every_run, int every_ref,
               int ref_pieces = 1, SpatialScheme scheme = SpatialScheme::kRk4) {
  for (auto _ : state) {
    const Run run = Simulate(40, 2e-3, every_run, 1e-10, 1, scheme);
    const Run ref = Simulate(ref_nodes, ref_dt, every_ref, 1e-10, ref_pieces);
    if (!run.ok || !ref.ok) state.SkipWithError("a step failed");
    double worst = 0, worst_1s = 0, worst_5s = 0;
    const size_t n = std::min(run.tip.size(), ref.tip.size());
    const double frame_dt = 2e-3 * every_run;
    for (size_t k = 0; k < n; ++k) {
      const double d = (run.tip[k] - ref.tip[k]).norm();
      worst = std::max(worst, d);
      if (k * frame_dt <= 1.0 + 1e-9) worst_1s = std::max(worst_1s, d);
      if (k * frame_dt <= 5.0 + 1e-9) worst_5s = std::max(worst_5s, d);
    }
    state.counters["max_tip_diff_mm"] = worst * 1e3;
    state.counters["max_tip_diff_over_L"] = worst / kLength;
    state.counters["first_1s_mm"] = worst_1s * 1e3;
    state.counters["first_5s_mm"] = worst_5s * 1e3;
  }
}

void BM_PeerRelease(benchmark::State& state) { PeerRelease(state, SpatialScheme::kRk4); }
void BM_PeerReleaseHeun(benchmark::State& state) { PeerRelease(state, SpatialScheme::kHeun); }
// Each step's fastest of 5 passes: the p99 / median of the work itself (docs/performance.md,
// "The tail").
void BM_PeerReleaseHeunFastestOf5(benchmark::State& state) {
  PeerRelease(state, SpatialScheme::kHeun, 5);
}
void BM_PeerReleaseFastestOf5(benchmark::State& state) {
  PeerRelease(state, SpatialScheme::kRk4, 5);
}
// RK4 across pairs of segments, the default (19 pairs and one segment alone at 40 nodes).
void BM_PeerReleaseRk4Pairs(benchmark::State& state) {
  PeerRelease(state, SpatialScheme::kRk4Pairs);
}
void BM_PeerReleaseRk4PairsFastestOf5(benchmark::State& state) {
  PeerRelease(state, SpatialScheme::kRk4Pairs, 5);
}

void BM_PeerAccuracyGrid4x(benchmark::State& state) { CompareTo(state, 160, 2e-3, 1, 1); }
// Heun at 40 nodes against RK4 at 160 (same dt): the spatial error of the order-2 scheme.
void BM_PeerAccuracyHeunGrid4x(benchmark::State& state) {
  CompareTo(state, 160, 2e-3, 1, 1, 1, SpatialScheme::kHeun);
}
void BM_PeerAccuracyRk4PairsGrid4x(benchmark::State& state) {
  CompareTo(state, 160, 2e-3, 1, 1, 1, SpatialScheme::kRk4Pairs);
}

// dt/2 and 4× the grid at once: every 2nd reference frame is every frame of the 2 ms run.
void BM_PeerAccuracyDtHalfGrid4x(benchmark::State& state) { CompareTo(state, 160, 1e-3, 1, 2); }

// The fine reference: dt/8 and 4× the grid, 8 shooting pieces (about a minute).
void BM_PeerAccuracyDt8Grid4x(benchmark::State& state) { CompareTo(state, 160, 2.5e-4, 1, 8, 8); }
void BM_PeerAccuracyHeunDt8Grid4x(benchmark::State& state) {
  CompareTo(state, 160, 2.5e-4, 1, 8, 8, SpatialScheme::kHeun);
}
void BM_PeerAccuracyRk4PairsDt8Grid4x(benchmark::State& state) {
  CompareTo(state, 160, 2.5e-4, 1, 8, 8, SpatialScheme::kRk4Pairs);
}

}  // namespace

BENCHMARK(BM_PeerRelease)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerReleaseHeun)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerReleaseFastestOf5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerReleaseHeunFastestOf5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerReleaseRk4Pairs)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerReleaseRk4PairsFastestOf5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyGrid4x)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyHeunGrid4x)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyRk4PairsGrid4x)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyDtHalfGrid4x)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyDt8Grid4x)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyHeunDt8Grid4x)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_PeerAccuracyRk4PairsDt8Grid4x)->Iterations(1)->Unit(benchmark::kSecond);
