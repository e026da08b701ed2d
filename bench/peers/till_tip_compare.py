#!/usr/bin/env python3
"""Largest tip distance between a `cosserat solve` dynamics run and the tip trajectory written by
the Till, Aloi & Rucker binary of bench/peers/till_release.sh, over [0, T] for several T.

    python3 bench/peers/till_tip_compare.py OURS.json|OURS.csv THEIRS.csv [T ...]

OURS: our result JSON (trajectory.tip_position) or our --csv trajectory table (the node with the
largest index is the tip). THEIRS: "t,x,z" rows (their code keeps x and z only; y is 0 by
symmetry in both codes for this problem). Frames whose times agree to 1 µs are compared.
Standard library only.
"""
import csv
import json
import math
import sys


def ours(path):
    if path.endswith(".json"):
        with open(path) as f:
            t = json.load(f)["trajectory"]
        return {round(time, 6): (p[0], p[2]) for time, p in zip(t["t"], t["tip_position"])}
    frames = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            frames.setdefault(round(float(row["t"]), 6), {})[int(row["node"])] = (float(row["x"]), float(row["z"]))
    return {t: nodes[max(nodes)] for t, nodes in frames.items()}


def theirs(path):
    with open(path) as f:
        return {round(float(r["t"]), 6): (float(r["x"]), float(r["z"])) for r in csv.DictReader(f)}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    a, b = ours(sys.argv[1]), theirs(sys.argv[2])
    windows = [float(x) for x in sys.argv[3:]] or [0.0, 1.0, 5.0, 25.0]
    common = sorted(set(a) & set(b))
    if not common:
        sys.exit("no common frame times")
    for T in windows:
        ts = [t for t in common if t <= T + 1e-9]
        worst = max(math.dist(a[t], b[t]) for t in ts)
        print(f"max tip distance over [0, {T:g}] s: {worst * 1e3:8.3f} mm ({len(ts)} frames)")


if __name__ == "__main__":
    main()
