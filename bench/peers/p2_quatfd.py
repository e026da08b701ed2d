#!/usr/bin/env python3
"""P2 for the quaternion-FD path: the soft cantilever (bench/problems/soft_cantilever.json, here
tests/cli/soft_cantilever_quatfd.json: 1 ms frames, released undamped) against PyElastica, both
codes' runs alternating in the same minutes, each code's error against its own converged
reference (bench/peers/README.md, "Accuracy against cost").

    /usr/bin/python3 bench/peers/p2_quatfd.py --cosserat build/apps/cosserat \
        --elastica /work/peers/PyElastica [--rounds 2] [--csv OUT.csv]

Ours: the quaternion-FD path (Radau IIA) at 21 / 31 / 51 / 101 nodes and integrator tolerances 1e-6 (the
default) and 1e-2; a whole `cosserat solve` process, CPU = user + sys (os.wait4). PyElastica:
100 / 200 / 400 elements at their largest stable dt (5e-5, 2.5e-5, 2e-5 s); CPU of the stepping
loop alone as bench/peers/pyelastica_cantilever.py reports it (imports and numba compilation not
counted, in their favour). Errors: the largest tip distance, % of L, over [0, 0.5] s and
[0, 1] s, against results/ref_cosserat_backward_euler_start_extrapolated.csv (ours) and
results/ref_pyelastica_extrapolated.csv (theirs). Prints one row per configuration: median CPU
per simulated second over the rounds and the errors (the same in every round).
"""
import argparse
import copy
import csv
import json
import os
import statistics
import sys
import tempfile

import compare_tip_trajectories as ctt
from interleave import run_pyelastica, timed

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
DURATION = 1.0
LENGTH = 0.3  # m, the soft cantilever's
OURS = [(nodes, tol) for nodes in (21, 31, 51, 101) for tol in (1e-6, 1e-2)]
THEIRS = [(100, 5e-5), (200, 2.5e-5), (400, 2e-5)]


def tip_error(run_csv, ref, until):
    """Largest tip distance to the reference rows over [0, until], % L."""
    return 100.0 * ctt.max_distance(ctt.read_tip(run_csv)[1], ref, until) / LENGTH


def run_ours(binary, nodes, tol, tmp):
    with open(os.path.join(REPO, "tests/cli/soft_cantilever_quatfd.json")) as f:
        problem = json.load(f)
    problem = copy.deepcopy(problem)
    problem["rod"]["nodes"] = nodes
    problem["dynamics"]["duration"] = DURATION
    problem["dynamics"]["integrator_tolerance"] = tol
    path = os.path.join(tmp, f"q{nodes}_{tol:g}.json")
    with open(path, "w") as f:
        json.dump(problem, f)
    trajectory = os.path.join(tmp, f"q{nodes}_{tol:g}.csv")
    code, _, err, _, cpu, _ = timed([binary, "solve", path, "--out", os.path.join(tmp, "r.json"),
                                     "--csv", trajectory])
    if code != 0:
        sys.exit(f"cosserat failed on {nodes} nodes, tolerance {tol:g}:\n{err}")
    return cpu, trajectory


def run_theirs(elastica, elements, dt, tmp):
    trajectory = os.path.join(tmp, f"e{elements}.csv")
    report, _, _, _ = run_pyelastica(elastica, elements, dt, DURATION, trajectory)
    return report["cpu_s"], trajectory  # the stepping loop alone


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cosserat", required=True)
    ap.add_argument("--elastica", required=True, help="PyElastica source directory")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--csv", help="write every run here")
    a = ap.parse_args()
    binary = os.path.abspath(a.cosserat)
    ref_ours = ctt.read_tip(
        os.path.join(HERE, "results/ref_cosserat_backward_euler_start_extrapolated.csv"))[1]
    ref_theirs = ctt.read_tip(os.path.join(HERE, "results/ref_pyelastica_extrapolated.csv"))[1]
    rows, errors = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        for rnd in range(a.rounds):
            # Alternate: one of ours, one of theirs, ...; the order rotates each round.
            jobs = []
            for k in range(max(len(OURS), len(THEIRS))):
                if k < len(OURS):
                    jobs.append(("cosserat",) + OURS[k])
                if k < len(THEIRS):
                    jobs.append(("pyelastica",) + THEIRS[k])
            shift = rnd % len(jobs)
            for job in jobs[shift:] + jobs[:shift]:
                if job[0] == "cosserat":
                    cpu, path = run_ours(binary, job[1], job[2], tmp)
                    ref = ref_ours
                    name = f"quaternion-FD {job[1]} nodes, tol {job[2]:g}"
                else:
                    cpu, path = run_theirs(a.elastica, job[1], job[2], tmp)
                    ref = ref_theirs
                    name = f"PyElastica {job[1]} elements, dt {job[2]:g}"
                if name not in errors:
                    errors[name] = (tip_error(path, ref, 0.5), tip_error(path, ref, 1.0))
                rows.append({"round": rnd, "run": name, "cpu_s": cpu})
                print(f"round {rnd}: {name}: {cpu:.3f} s CPU", flush=True)
    print(f"\n{'configuration':<36} {'CPU s per simulated s':>22} {'error [0, 0.5] s':>17} "
          f"{'[0, 1] s':>9}  (% L, each against its own reference)")
    for name in errors:
        cpu = statistics.median(r["cpu_s"] for r in rows if r["run"] == name) / DURATION
        e05, e1 = errors[name]
        print(f"{name:<36} {cpu:>22.3f} {e05:>16.3f}% {e1:>8.3f}%")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["round", "run", "cpu_s"])
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
