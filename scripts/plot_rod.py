#!/usr/bin/python3
"""Plot a `cosserat solve` result: the centreline in two side views and the curvature along s,
and for a dynamics result (one with a "trajectory") the tip x, y, z against time, with the
tip's spin (a drill string's trajectory.tip_spin), a motor-driven table's speed and torque, and
the anchor's tension (|trajectory.
anchor_force|, a riser's top tension) when the result has them. With the
problem file, its contact surfaces and the rod's outer surface are drawn in the side views; a
result with contact also
shows the contact force per unit length along s.

Usage: plot_rod.py RESULT.json OUT.png [--problem PROBLEM.json]
Uses Debian's python3-matplotlib (run it with /usr/bin/python3).
"""
import json
import math
import os
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


def plot_surfaces(axes, problem):
    """The problem's contact surfaces in the x–z and y–z views (their traces in those planes)."""
    views = [(0, 2), (1, 2)]
    for surface in problem.get("environment", {}).get("contact", []):
        shape = surface["shape"]
        for ax, (h, v) in zip(axes, views):
            x0, x1 = ax.get_xlim()
            y0, y1 = ax.get_ylim()
            span = max(x1 - x0, y1 - y0)
            style = dict(color="0.35", lw=1.2)
            if shape == "sphere":
                c, r = surface["center"], surface["radius"]
                ax.add_patch(plt.Circle((c[h], c[v]), r, fill=True, fc="0.85", ec="0.35"))
            elif shape == "plane":
                p, n = surface.get("point", [0, 0, 0]), surface["normal"]
                # The trace of the plane n·(q − p) = 0 in the view: a line along (n_v, −n_h).
                d = (n[v], -n[h])
                if math.hypot(*d) == 0:
                    continue
                ax.plot([p[h] - span * d[0], p[h] + span * d[0]],
                        [p[v] - span * d[1], p[v] + span * d[1]], **style)
            else:  # cylinder: a circle seen along its axis, else its two walls
                p, a, r = surface.get("point", [0, 0, 0]), surface["axis"], surface["radius"]
                norm = math.sqrt(sum(c * c for c in a))
                a = [c / norm for c in a]
                if math.hypot(a[h], a[v]) < 1e-9:
                    ax.add_patch(plt.Circle((p[h], p[v]), r, fill=False, ec="0.35", lw=1.2))
                    continue
                along = (a[h] / math.hypot(a[h], a[v]), a[v] / math.hypot(a[h], a[v]))
                side = (-along[1], along[0])
                for sign in (-1, 1):
                    cx, cy = p[h] + sign * r * side[0], p[v] + sign * r * side[1]
                    ax.plot([cx - span * along[0], cx + span * along[0]],
                            [cy - span * along[1], cy + span * along[1]], **style)
            ax.set_xlim(x0, x1)
            ax.set_ylim(y0, y1)


def plot_outline(axes, result, problem):
    """The rod's outer surface in the side views (the centreline offset by the outer radius
    across its tangent), so contact with a surface shows as touching."""
    section = problem["rod"].get("section", {})
    radius = section.get("outer_radius", section.get("radius"))
    if not radius:
        return
    position = result["nodes"]["position"]
    for ax, (h, v) in zip(axes, [(0, 2), (1, 2)]):
        pts = [(p[h], p[v]) for p in position]
        for sign in (-1, 1):
            line = []
            for i, (x, y) in enumerate(pts):
                a, b = pts[max(i - 1, 0)], pts[min(i + 1, len(pts) - 1)]
                tx, ty = b[0] - a[0], b[1] - a[1]
                norm = math.hypot(tx, ty)
                if norm == 0:
                    continue
                line.append((x - sign * radius * ty / norm, y + sign * radius * tx / norm))
            if line:
                ax.plot(*zip(*line), color="C0", lw=0.8, alpha=0.6)


def plot_contact_force(ax, result):
    """|contact force| per unit length along s, on a second axis of the curvature panel."""
    force = result["nodes"].get("contact_force")
    if not force:
        return
    twin = ax.twinx()
    twin.plot(result["nodes"]["s"], [math.sqrt(sum(c * c for c in f)) for f in force], "k--",
              lw=1.0, label="|contact force|")
    twin.set_ylabel("contact force [N/m]")
    twin.legend(loc="lower right")


def trajectory_strips(trajectory):
    """(label, values) of each strip: tip x, y, z, then the extras the trajectory holds."""
    columns = list(zip(*trajectory["tip_position"]))
    strips = [(f"tip {name} [m]", values) for name, values in zip("xyz", columns)]
    if "tip_spin" in trajectory:
        strips.append(("tip spin [rad/s]", trajectory["tip_spin"]))
    if "table_speed" in trajectory:
        strips.append(("table [rad/s]", trajectory["table_speed"]))
        strips.append(("on table [kN·m]", [m / 1e3 for m in trajectory["table_torque"]]))
    if "anchor_force" in trajectory:
        tension = [math.sqrt(sum(c * c for c in f)) / 1e3 for f in trajectory["anchor_force"]]
        strips.append(("anchor tension [kN]", tension))
    return strips


def plot_trajectory(axes, trajectory):
    """Each strip against t, one axis each (their ranges can differ by orders of magnitude)."""
    t = trajectory["t"]
    for k, (ax, (label, values)) in enumerate(zip(axes, trajectory_strips(trajectory))):
        ax.plot(t, values, color=f"C{k}", lw=1.0)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].set_title("tip against time")
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
    problem = None
    if len(argv) == 5 and argv[3] == "--problem":
        with open(argv[4]) as f:
            problem = json.load(f)
        argv = argv[:3]
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
        if problem:
            plot_surfaces(axes[:2], problem)
            plot_outline(axes[:2], result, problem)
        plot_contact_force(axes[2], result)
    else:
        count = len(trajectory_strips(trajectory))
        fig = plt.figure(figsize=(13, 5.6 + 0.95 * count))
        grid = fig.add_gridspec(2, 1, height_ratios=[3, count])
        top = grid[0].subgridspec(1, 3)
        shape_axes = [fig.add_subplot(top[0, i]) for i in range(3)]
        plot_shape(shape_axes, result)
        if problem:
            plot_surfaces(shape_axes[:2], problem)
            plot_outline(shape_axes[:2], result, problem)
        plot_contact_force(shape_axes[2], result)
        bottom = grid[1].subgridspec(count, 1, hspace=0.08)
        strips = [fig.add_subplot(bottom[i, 0]) for i in range(count)]
        for ax in strips[:-1]:
            ax.sharex(strips[-1])
            ax.tick_params(labelbottom=False)
        plot_trajectory(strips, trajectory)
    fig.suptitle(title(result))
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(argv[2])), exist_ok=True)
    fig.savefig(argv[2], dpi=120)
    print(f"plot written to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
