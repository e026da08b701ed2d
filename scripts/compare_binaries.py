#!/usr/bin/env python3
"""Runs every problem file of examples/, robots/ and tests/cli/ with two `cosserat` binaries and
compares what they report: exit code, status, the tip and every node position (statics and the
final state of dynamics), and the tip trajectory, in units of the rod length L.

    scripts/compare_binaries.py OLD_BINARY NEW_BINARY [--tol 1e-9] [--only SUBSTRING]

Prints one line per problem and exits 1 when any problem differs by more than --tol L or in its
exit code or status. Standard library only."""
import argparse
import json
import math
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def run(binary, problem, out):
    proc = subprocess.run([binary, "solve", str(problem), "--out", str(out)],
                          capture_output=True, text=True, cwd=ROOT, timeout=900)
    result = None
    if out.exists():
        with open(out) as f:
            result = json.load(f)
    return proc.returncode, result


def points(result):
    """Every position the result reports, as a flat list of 3-vectors."""
    pts = []
    if not isinstance(result, dict):
        return pts
    tip = result.get("tip")
    if isinstance(tip, dict) and tip.get("position"):
        pts.append(tip["position"])
    nodes = result.get("nodes")
    if isinstance(nodes, dict) and nodes.get("position"):
        pts.extend(nodes["position"])
    traj = result.get("trajectory")
    if isinstance(traj, dict) and traj.get("tip_position"):
        pts.extend(traj["tip_position"])
    return pts


def distance(a, b):
    if a is None or b is None or None in a or None in b:
        return 0.0 if a == b else math.inf
    return math.dist(a, b)


def length_of(problem):
    try:
        with open(problem) as f:
            return float(json.load(f)["rod"]["length"])
    except Exception:
        return 1.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--tol", type=float, default=1e-9, help="largest distance, in L")
    parser.add_argument("--only", default="", help="run only problems whose path contains this")
    args = parser.parse_args()
    problems = sorted(p for d in ("examples", "robots", "tests/cli")
                      for p in (ROOT / d).glob("*.json") if args.only in str(p))
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for problem in problems:
            rel = problem.relative_to(ROOT)
            code_a, res_a = run(args.old, problem, pathlib.Path(tmp) / "a.json")
            code_b, res_b = run(args.new, problem, pathlib.Path(tmp) / "b.json")
            for f in ("a.json", "b.json"):
                (pathlib.Path(tmp) / f).unlink(missing_ok=True)
            status_a = res_a.get("status") if isinstance(res_a, dict) else None
            status_b = res_b.get("status") if isinstance(res_b, dict) else None
            pa, pb = points(res_a), points(res_b)
            worst = 0.0 if len(pa) == len(pb) else math.inf
            for a, b in zip(pa, pb):
                worst = max(worst, distance(a, b))
            worst /= length_of(problem)
            same = code_a == code_b and status_a == status_b and worst <= args.tol
            failures += not same
            print(f"{'ok  ' if same else 'DIFF'} {rel}: exit {code_a}/{code_b}, "
                  f"status {status_a}/{status_b}, {len(pa)} points, max distance {worst:.2e} L")
    print(f"{len(problems) - failures} same, {failures} different")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
