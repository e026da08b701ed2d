#!/usr/bin/env python3
"""Distance between two tip trajectories, as a fraction of the rod length.

  compare_tip_trajectories.py A.csv B.csv [--length 0.3] [--until 1.0] [--json]

Each file is either
  - a tip table with header "t,x,y,z" (bench/peers/pyelastica_cantilever.py), or
  - a trajectory table with header "t,node,s,x,y,z" (cosserat solve --csv for dynamics, or
    pyelastica_cantilever.py --all-nodes): the row of the last node of each frame is the tip.
The header decides which. The file with fewer frames in [0, until] gives the comparison times;
the other is interpolated onto them (cubic spline per coordinate with scipy, else linear), so
keep the denser file's frames at least as fine as the coarser one's. Prints the maximum and RMS
tip distance over the comparison times as a fraction of --length, and when the maximum occurs.
"""
import argparse
import csv
import json
import math
import sys


def read_tip(path):
    with open(path, newline="") as f:
        r = csv.reader(f)
        header = [h.strip() for h in next(r)]
        if header[:4] == ["t", "x", "y", "z"]:
            rows = [(float(a[0]), float(a[1]), float(a[2]), float(a[3])) for a in r if a]
            fmt = "tip"
        elif header[:6] == ["t", "node", "s", "x", "y", "z"]:
            last = {}
            order = []
            for a in r:
                if not a:
                    continue
                t = float(a[0])
                node = int(a[1])
                if t not in last:
                    order.append(t)
                    last[t] = (node, a)
                elif node > last[t][0]:
                    last[t] = (node, a)
            rows = []
            for t in order:
                a = last[t][1]
                rows.append((t, float(a[3]), float(a[4]), float(a[5])))
            fmt = "trajectory"
        else:
            sys.exit("%s: unknown header %s (expected t,x,y,z or t,node,s,x,y,z)" % (path, ",".join(header)))
    rows.sort()
    # drop duplicate times (a final state that coincides with a frame)
    out = []
    for row in rows:
        if out and abs(row[0] - out[-1][0]) < 1e-12:
            out[-1] = row
        else:
            out.append(row)
    return fmt, out


def interpolator(rows):
    ts = [r[0] for r in rows]
    cols = [[r[i] for r in rows] for i in (1, 2, 3)]
    try:
        from scipy.interpolate import CubicSpline

        splines = [CubicSpline(ts, c) for c in cols]
        return lambda t: [float(s(t)) for s in splines], "cubic"
    except ImportError:
        import bisect

        def lin(t):
            j = min(max(bisect.bisect_right(ts, t), 1), len(ts) - 1)
            w = (t - ts[j - 1]) / (ts[j] - ts[j - 1])
            return [c[j - 1] + w * (c[j] - c[j - 1]) for c in cols]

        return lin, "linear"


def max_distance(rows, ref, until=math.inf):
    """The largest distance (m) from the tip rows (t, x, y, z) with t <= until, and not past the
    end of the reference rows `ref`, to `ref` interpolated at their times."""
    f, _ = interpolator(ref)
    t_end = min(until, ref[-1][0])
    d = 0.0
    for t, x, y, z in rows:
        if t > t_end + 1e-9:
            break
        p = f(t)
        d = max(d, math.sqrt((p[0] - x) ** 2 + (p[1] - y) ** 2 + (p[2] - z) ** 2))
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--length", type=float, default=0.3)
    ap.add_argument("--until", type=float, default=1.0)
    ap.add_argument("--json", action="store_true", help="print one JSON line instead of text")
    args = ap.parse_args()

    fa, ra = read_tip(args.a)
    fb, rb = read_tip(args.b)
    eps = 1e-9
    ina = [r for r in ra if r[0] <= args.until + eps]
    inb = [r for r in rb if r[0] <= args.until + eps]
    coarse, dense = (ina, rb) if len(ina) <= len(inb) else (inb, ra)
    t_lo, t_hi = dense[0][0], dense[-1][0]
    grid = [r for r in coarse if t_lo - eps <= r[0] <= t_hi + eps]
    if len(grid) < 2:
        sys.exit("fewer than two common times in [0, %g]" % args.until)
    f, kind = interpolator(dense)
    dmax, tmax, s2 = -1.0, None, 0.0
    for r in grid:
        p = f(r[0])
        d = math.sqrt((p[0] - r[1]) ** 2 + (p[1] - r[2]) ** 2 + (p[2] - r[3]) ** 2)
        s2 += d * d
        if d > dmax:
            dmax, tmax = d, r[0]
    rms = math.sqrt(s2 / len(grid))
    covered = grid[-1][0]
    res = {
        "a": args.a, "a_format": fa, "b": args.b, "b_format": fb,
        "times": len(grid), "from_t": grid[0][0], "to_t": covered, "interpolation": kind,
        "max_over_L": dmax / args.length, "rms_over_L": rms / args.length, "t_of_max": tmax,
    }
    if args.json:
        print(json.dumps(res))
    else:
        print("tip distance over t in [%g, %g] (%d times, %s interpolation): max %.4g %% L at t = %g s, RMS %.4g %% L"
              % (grid[0][0], covered, len(grid), kind, 100 * dmax / args.length, tmax, 100 * rms / args.length))
    if covered < args.until - 1e-6:
        print("warning: the trajectories cover only [0, %g] of [0, %g]" % (covered, args.until), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
