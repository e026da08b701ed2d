#!/usr/bin/python3
"""Plot the mode shapes of a `cosserat solve` modes result: each mode's displacement along s,
split into its out-of-plane part (along the normal of the plane that holds the equilibrium's
chord and its sag, e.g. sideways for a stay cable) and its in-plane part (within that plane,
across the chord), each mode scaled to a largest displacement of 1, with its frequency.

Usage: plot_modes.py RESULT.json OUT.png [--count N]
Uses Debian's python3-matplotlib and python3-numpy (run it with /usr/bin/python3).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def plane_axes(positions):
    """The chord's direction and the unit normals across it, in and out of the equilibrium's
    plane (the plane of the chord and the point farthest from it)."""
    p = np.asarray(positions)
    chord = p[-1] - p[0]
    chord /= np.linalg.norm(chord)
    offsets = p - p[0]
    across = offsets - np.outer(offsets @ chord, chord)
    far = across[np.argmax(np.linalg.norm(across, axis=1))]
    if np.linalg.norm(far) < 1e-12:  # straight: any normal
        far = np.cross(chord, [0.0, 0.0, 1.0])
        if np.linalg.norm(far) < 1e-12:
            far = np.cross(chord, [1.0, 0.0, 0.0])
    in_plane = far / np.linalg.norm(far)
    return chord, in_plane, np.cross(chord, in_plane)


def main(argv):
    count = None
    if len(argv) == 5 and argv[3] == "--count":
        count = int(argv[4])
        argv = argv[:3]
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1]) as f:
        result = json.load(f)
    modes = result.get("modes")
    if not modes or not modes.get("shapes"):
        sys.stderr.write(f"{argv[1]}: no mode shapes (status: {result.get('status')})\n")
        return 1
    _, in_plane, out_of_plane = plane_axes(result["nodes"]["position"])
    s = np.asarray(modes["s"])
    shapes = modes["shapes"][:count]
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    for k, (shape, f) in enumerate(zip(shapes, modes["frequencies_hz"])):
        u = np.asarray(shape["displacement"])
        a, b = u @ out_of_plane, u @ in_plane
        scale = max(np.abs(a).max(), np.abs(b).max(), 1e-300)
        out = np.abs(a).max() >= np.abs(b).max()  # the mode's larger part decides its panel
        part, ax = (a, axes[0]) if out else (b, axes[1])
        ax.plot(s, part / scale, lw=1.2, label=f"mode {k + 1}: {f:.4g} Hz")
    axes[0].set_title("out of the equilibrium's plane")
    axes[1].set_title("in the equilibrium's plane, across the chord")
    for ax in axes:
        ax.set_ylabel("displacement (scaled)")
        ax.grid(True, alpha=0.3)
        if ax.lines:
            ax.legend(loc="upper right", fontsize=8)
    axes[1].set_xlabel("s [m]")
    fig.suptitle(f"status: {result['status']}, {len(shapes)} modes ({modes['formulation']})")
    fig.tight_layout()
    fig.savefig(argv[2], dpi=120)
    print(f"plot written to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
