#!/usr/bin/python3
"""Plot a `cosserat solve` result: the centreline in two side views and the curvature along s,
and for a dynamics result (one with a "trajectory") the tip x, y, z against time.

Usage: plot_rod.py RESULT.json OUT.png
Uses Debian's python3-matplotlib (run it with /usr/bin/python3).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def plot_shape(axes, result):
    """Centreline side views and curvature of the (final) state."""
    nodes = result["nodes"]
    s = nodes["s"]
    x, y, z = zip(*nodes["position"])
    k1, k2, k3 = zip(*nodes["curvature"])
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


def plot_trajectory(axes, trajectory):
    """Tip x, y, z against t, one strip each (their ranges can differ by orders of magnitude)."""
    t = trajectory["t"]
    columns = list(zip(*trajectory["tip_position"]))
    for ax, values, name, colour in zip(axes, columns, "xyz", ["C0", "C1", "C2"]):
        ax.plot(t, values, color=colour, lw=1.0)
        ax.set_ylabel(f"tip {name} [m]")
        ax.grid(True, alpha=0.3)
    axes[0].set_title("tip position against time")
    axes[-1].set_xlabel("t [s]")


def title(result):
    tip = result["tip"]["position"]
    where = f"tip = ({tip[0]:.4f}, {tip[1]:.4f}, {tip[2]:.4f}) m"
    if "trajectory" in result:
        return (
            f"status: {result['status']}, {result['steps']} steps, "
            f"t = {result['simulated_time_s']:g} s (final state), {where}"
        )
    return f"status: {result['status']}, iterations {result['iterations']}, {where}"


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1]) as f:
        result = json.load(f)
    if "nodes" not in result:
        sys.stderr.write(f"{argv[1]}: no rod state to plot (status: {result.get('status')})\n")
        return 1

    trajectory = result.get("trajectory")
    if trajectory is None:
        fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
        plot_shape(axes, result)
    else:
        fig = plt.figure(figsize=(13, 8.4))
        grid = fig.add_gridspec(2, 1, height_ratios=[1, 1])
        top = grid[0].subgridspec(1, 3)
        plot_shape([fig.add_subplot(top[0, i]) for i in range(3)], result)
        bottom = grid[1].subgridspec(3, 1, hspace=0.08)
        strips = [fig.add_subplot(bottom[i, 0]) for i in range(3)]
        for ax in strips[:-1]:
            ax.sharex(strips[-1])
            ax.tick_params(labelbottom=False)
        plot_trajectory(strips, trajectory)
    fig.suptitle(title(result))
    fig.tight_layout()
    fig.savefig(argv[2], dpi=120)
    print(f"plot written to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
