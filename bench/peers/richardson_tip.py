#!/usr/bin/env python3
"""Richardson extrapolation of a tip trajectory from two resolutions.

  richardson_tip.py FINE.csv COARSE.csv --out REF.csv [--ratio 2] [--order 1] [--until 1.0]

FINE and COARSE are tip trajectories in either format of compare_tip_trajectories.py, FINE
refined by --ratio (in dt or in the element size) over COARSE. At FINE's frame times (COARSE is
interpolated onto them) it writes "t,x,y,z" of FINE + (FINE - COARSE) / (ratio^order - 1).
Check the order first: successive differences of three resolutions should shrink by ratio^order.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_tip_trajectories as ctt  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("fine")
ap.add_argument("coarse")
ap.add_argument("--out", required=True)
ap.add_argument("--ratio", type=float, default=2.0)
ap.add_argument("--order", type=float, default=1.0)
ap.add_argument("--until", type=float, default=1.0)
a = ap.parse_args()
_, fine = ctt.read_tip(a.fine)
_, coarse = ctt.read_tip(a.coarse)
f, _ = ctt.interpolator(coarse)
w = 1.0 / (a.ratio ** a.order - 1.0)
t_hi = min(a.until, coarse[-1][0]) + 1e-9
with open(a.out, "w") as out:
    out.write("t,x,y,z\n")
    for t, x, y, z in fine:
        if t > t_hi:
            break
        c = f(t)
        out.write("%.9g,%.17g,%.17g,%.17g\n" % (t, x + w * (x - c[0]), y + w * (y - c[1]), z + w * (z - c[2])))
