#!/usr/bin/python3
"""Plot a `cosserat solve` result: the centreline in two side views and the curvature along s.

Usage: plot_rod.py RESULT.json OUT.png
Uses Debian's python3-matplotlib (run it with /usr/bin/python3).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1]) as f:
        result = json.load(f)
    nodes = result["nodes"]
    s = nodes["s"]
    x, y, z = zip(*nodes["position"])
    k1, k2, k3 = zip(*nodes["curvature"])

    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    for ax, (h, v, hl, vl) in zip(axes[:2], [(x, z, "x", "z"), (y, z, "y", "z")]):
        ax.plot(h, v, "-o", ms=2.5, lw=1.5)
        ax.plot(h[0], v[0], "ks", ms=7, label="base")
        ax.plot(h[-1], v[-1], "r^", ms=7, label="tip")
        ax.set_xlabel(f"{hl} [m]")
        ax.set_ylabel(f"{vl} [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
        ax.set_title(f"centreline, {vl}–{hl} view")
    axes[0].legend(loc="best")
    axes[2].plot(s, k1, label="κ1 (about body x)")
    axes[2].plot(s, k2, label="κ2 (about body y)")
    axes[2].plot(s, k3, label="κ3 (torsion)")
    axes[2].set_xlabel("s [m]")
    axes[2].set_ylabel("curvature [1/m]")
    axes[2].grid(True, alpha=0.3)
    axes[2].legend(loc="best")
    tip = result["tip"]["position"]
    fig.suptitle(
        f"status: {result['status']}, iterations {result['iterations']}, "
        f"tip = ({tip[0]:.4f}, {tip[1]:.4f}, {tip[2]:.4f}) m"
    )
    fig.tight_layout()
    fig.savefig(argv[2], dpi=120)
    print(f"plot written to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
