#!/usr/bin/env python3
"""A/B timing of two builds of cosserat, interleaved in the same minutes: the peer release as a
whole `cosserat solve` process (default settings, RK4 and Heun in s), the warm static re-solve and the Lang & Linn
rubber rod with Radau IIA and the 1 000-point workspace sweep. Prints each case's median time for A and B and the ratio B/A.

    scripts/ab_benchmark.py BUILD_A BUILD_B [--rounds 5]

BUILD_* are build directories (with apps/cosserat and bench/bench_static, bench/bench_quatfd).
Standard library only."""
import argparse
import json
import pathlib
import statistics
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent


def solve_seconds(build, problem):
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        subprocess.run([str(build / "apps/cosserat"), "solve", str(ROOT / problem), "--out",
                        str(pathlib.Path(tmp) / "r.json")], check=True, capture_output=True)
        return time.perf_counter() - start


def bench_seconds(build, binary, name):
    out = subprocess.run([str(build / "bench" / binary), f"--benchmark_filter=^{name}$",
                          "--benchmark_format=json"], check=True, capture_output=True, text=True)
    runs = json.loads(out.stdout)["benchmarks"]
    unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[runs[0]["time_unit"]]
    return runs[0]["real_time"] * unit


CASES = [
    ("peer release, default settings (whole process)", lambda b: solve_seconds(b, "examples/cantilever_release.json")),
    ("peer release, RK4 (whole process)", lambda b: solve_seconds(b, "bench/problems/peer_rk4.json")),
    ("peer release, Heun (whole process)", lambda b: solve_seconds(b, "bench/problems/peer_heun.json")),
    ("warm static re-solve, 41 nodes", lambda b: bench_seconds(b, "bench_static", "BM_StaticResolveWarm1Percent/41")),
    ("warm static re-solve, 101 nodes", lambda b: bench_seconds(b, "bench_static", "BM_StaticResolveWarm1Percent/101")),
    ("rubber rod, Radau, 10 segments", lambda b: bench_seconds(b, "bench_quatfd", "BM_RubberRod_Radau/10/iterations:1")),
    ("1 000-point sweep, 1 thread", lambda b: bench_seconds(b, "bench_sweep", "BM_TendonWorkspace1000/1/iterations:1/real_time")),
    ("1 000-point sweep, 2 threads", lambda b: bench_seconds(b, "bench_sweep", "BM_TendonWorkspace1000/2/iterations:1/real_time")),
]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a", type=pathlib.Path)
    parser.add_argument("b", type=pathlib.Path)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    for label, measure in CASES:
        times = {"a": [], "b": []}
        for r in range(args.rounds):  # A B, then B A: neither always runs first
            order = ("a", "b") if r % 2 == 0 else ("b", "a")
            for which in order:
                times[which].append(measure(getattr(args, which)))
        ma, mb = statistics.median(times["a"]), statistics.median(times["b"])
        print(f"{label:38s} A {ma * 1e3:9.3f} ms  B {mb * 1e3:9.3f} ms  B/A {mb / ma:.3f}  "
              f"(min B/A {min(times['b']) / min(times['a']):.3f})", flush=True)


if __name__ == "__main__":
    main()
