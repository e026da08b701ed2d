#!/usr/bin/env python3
"""Inverse kinematics of the continuum Stewart-Gough robot against Till, Aloi & Rucker's fastest
C++ example, in the same minutes: their program and ours (bench/bench_stewart_gough_ik) run the
same loop of 50 000 warm-started solves, alternately, `--rounds` times each, at two accuracies:
theirs as shipped (sum of squares 1e-6, a residual norm of 1e-3 in m, rad, N and N m) against ours
at 2.5e-3 (1 mm of position, 0.45 mN of force), and theirs at 1e-20 (a norm of 1e-10) against
ours at 1e-10 (0.04 nm, 18 pN). Prints each rate and the ratios (ours / theirs) of the medians.

  python3 bench/peers/csg_ik.py --ours build/bench/bench_stewart_gough_ik \\
      --src /work/peers/ContinuumRobotExamples [--rounds 3]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PAIRS = [("1e-6", "2.5e-3"), ("1e-20", "1e-10")]  # (their sum of squares, our tolerance)


def rate(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return float(re.search(r"Solution rate:\s*([0-9.]+)", out).group(1))


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("--ours", required=True)
    ap.add_argument("--src", required=True, help="a fetch of JohnDTill/ContinuumRobotExamples")
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args(argv[1:])
    with tempfile.TemporaryDirectory() as tmp:
        for theirs_tol, ours_tol in PAIRS:
            peer = os.path.join(tmp, f"till_{theirs_tol}")
            subprocess.run(["bash", os.path.join(HERE, "till_csg_ik.sh"), "--src", args.src,
                            "--out", peer, "--sos-tol", theirs_tol], check=True)
            ours, theirs = [], []
            for _ in range(args.rounds):
                ours.append(rate([args.ours, "--tolerance", ours_tol]))
                theirs.append(rate([peer]))
            print(f"theirs (sum of squares {theirs_tol}): "
                  + " ".join(f"{r:.0f}" for r in theirs) + " Hz")
            print(f"ours (tolerance {ours_tol}): " + " ".join(f"{r:.0f}" for r in ours) + " Hz")
            print(f"ratio of medians: {statistics.median(ours) / statistics.median(theirs):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
