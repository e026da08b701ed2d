#!/usr/bin/python3
"""Animate a dynamics problem: run it and write an MP4 (ffmpeg) or a GIF (Pillow).

Usage: animate_rod.py PROBLEM.json OUT.mp4|OUT.gif [--every N] [--fps F]
Uses the cosserat package (importable after the README's first command, or with
PYTHONPATH=build/python) and Debian's python3-matplotlib; MP4 needs ffmpeg (apt install ffmpeg).
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import cosserat  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("problem")
    ap.add_argument("out")
    ap.add_argument("--every", type=int, default=1, help="keep every n-th recorded frame")
    ap.add_argument("--fps", type=float, default=25)
    args = ap.parse_args()
    out = cosserat.solve(args.problem, nodes=True)
    sys.stderr.write(out["log"])
    if "frames" not in out:
        sys.exit(f"{args.problem}: not a dynamics problem of one rod (no frames to animate)")
    n = cosserat.animate(out, args.out, fps=args.fps, every=args.every)
    print(f"{n} frames written to {args.out}")
    return 0 if out["converged"] else 1


if __name__ == "__main__":
    sys.exit(main())
