#!/usr/bin/env python3
"""Largest distance between the tip trajectories of two `cosserat solve` dynamics results.

    scripts/compare_tips.py A.json B.json

Compares the frames whose times agree (to 1 µs) and prints the largest distance in mm and the
number of frames compared. Standard library only.
"""
import json
import math
import sys


def trajectory(path):
    with open(path) as f:
        t = json.load(f)["trajectory"]
    return {round(time, 6): p for time, p in zip(t["t"], t["tip_position"])}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = trajectory(sys.argv[1]), trajectory(sys.argv[2])
    common = sorted(set(a) & set(b))
    if not common:
        sys.exit("no common frame times")
    worst = max(math.dist(a[t], b[t]) for t in common)
    print(f"max tip distance {worst * 1e3:.3f} mm over {len(common)} frames "
          f"(t = {common[0]:g} .. {common[-1]:g} s)")


if __name__ == "__main__":
    main()
