#!/usr/bin/python3
"""Plot a `cosserat solve` result of an assembly: every rod's centreline in 3D and in two side
views, each body's frame at its pose (its axes 0.2 of the structure's size long), and for an
inverse problem the rods' lengths in the title.

Usage: plot_assembly.py RESULT.json OUT.png
Uses Debian's python3-matplotlib and python3-numpy (run it with /usr/bin/python3).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1]) as f:
        result = json.load(f)
    assembly = result.get("assembly")
    if not assembly:
        sys.stderr.write(f"{argv[1]}: not an assembly result (status: {result.get('status')})\n")
        return 1
    rods = [(r["name"], np.asarray(r["nodes"]["position"])) for r in assembly["rods"]]
    points = np.vstack([p for _, p in rods])
    size = float(np.ptp(points, axis=0).max()) or 1.0
    fig = plt.figure(figsize=(13, 4.6))
    ax3 = fig.add_subplot(1, 3, 1, projection="3d")
    views = [fig.add_subplot(1, 3, 2), fig.add_subplot(1, 3, 3)]
    for k, (name, p) in enumerate(rods):
        colour = f"C{k % 10}"
        ax3.plot(p[:, 0], p[:, 1], p[:, 2], color=colour, lw=1.5, label=name)
        views[0].plot(p[:, 0], p[:, 2], color=colour, lw=1.2)
        views[1].plot(p[:, 1], p[:, 2], color=colour, lw=1.2)
    for body in assembly["bodies"]:
        origin = np.asarray(body["position"])
        R = np.asarray(body["rotation"])
        for axis, colour in zip(range(3), ("r", "g", "b")):
            tip = origin + 0.2 * size * R[:, axis]
            ax3.plot(*zip(origin, tip), color=colour, lw=1.0)
        ax3.scatter(*origin, color="k", s=12)
        views[0].plot(origin[0], origin[2], "ks", ms=5)
        views[1].plot(origin[1], origin[2], "ks", ms=5)
    ax3.set_xlabel("x [m]")
    ax3.set_ylabel("y [m]")
    ax3.set_zlabel("z [m]")
    if len(rods) <= 8:
        ax3.legend(fontsize=7, loc="upper left")
    for ax, (a, b) in zip(views, (("x", "z"), ("y", "z"))):
        ax.set_xlabel(f"{a} [m]")
        ax.set_ylabel(f"{b} [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
        ax.set_title(f"{b}–{a} view")
    title = f"status: {result['status']}, {assembly.get('kind', '')} problem"
    if assembly.get("kind") == "inverse":
        title += ", lengths " + ", ".join(f"{r['length']:.4f}" for r in assembly["rods"]) + " m"
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=120)
    print(f"plot written to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
