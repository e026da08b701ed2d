#!/usr/bin/python3
"""Plot a `cosserat solve` result of an assembly: every rod's centreline in 3D and in two side
views, each body's frame at its pose (its axes 0.2 of the structure's size long), and for an
inverse problem the rods' lengths in the title. A dynamics result adds a row: each body's
displacement from its start against time, and the energy.

Usage: plot_assembly.py RESULT.json OUT.png
Uses Debian's python3-matplotlib and python3-numpy (run it with /usr/bin/python3).
"""
import json
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def plot_trajectory(trajectory, ax_pose, ax_energy):
    """Each body's displacement components (mm) and the total energy (J) against time (s)."""
    t = np.asarray(trajectory["t"])
    for k, body in enumerate(trajectory["bodies"]):
        p = np.asarray(body["position"])
        for axis, style in zip(range(3), ("-", "--", ":")):
            ax_pose.plot(t, 1e3 * (p[:, axis] - p[0, axis]), style, color=f"C{k % 10}",
                         lw=1.2, label=f"{body['name']} {'xyz'[axis]}")
    ax_pose.set_xlabel("t [s]")
    ax_pose.set_ylabel("displacement [mm]")
    ax_pose.legend(fontsize=7)
    ax_pose.grid(True, alpha=0.3)
    ax_energy.plot(t, trajectory["energy"], color="k", lw=1.2)
    ax_energy.set_xlabel("t [s]")
    ax_energy.set_ylabel("energy [J]")
    ax_energy.grid(True, alpha=0.3)


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
    trajectory = result.get("trajectory")
    rows = 2 if trajectory else 1
    fig = plt.figure(figsize=(13, 4.6 * rows))
    ax3 = fig.add_subplot(rows, 3, 1, projection="3d")
    views = [fig.add_subplot(rows, 3, 2), fig.add_subplot(rows, 3, 3)]
    if trajectory:
        plot_trajectory(trajectory, fig.add_subplot(2, 2, 3), fig.add_subplot(2, 2, 4))
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
    with warnings.catch_warnings():  # the trajectory row's two panels span the three above
        warnings.simplefilter("ignore")
        fig.tight_layout()
    fig.savefig(argv[2], dpi=120)
    print(f"plot written to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
