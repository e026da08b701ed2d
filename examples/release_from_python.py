#!/usr/bin/env python3
"""The peer release (examples/cantilever_release.json) stepped from Python, as a controller or a
notebook would: load the problem file, settle at rest under the preload, release, step, read
the tip.

    PYTHONPATH=build/python /usr/bin/python3 examples/release_from_python.py [seconds] [--heun] [--plot out.png]

Prints the real-time ratio of the stepping loop (Python call overhead included) and the tip's
range of swing; with --plot writes the tip's x(t) (needs python3-matplotlib).
"""
import argparse
import os
import time

import numpy as np

import cosserat

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("seconds", nargs="?", type=float, default=2.0, help="simulated time, s")
parser.add_argument("--heun", action="store_true", help="Heun in s instead of RK4")
parser.add_argument("--plot", help="write the tip's x(t) to this PNG")
args = parser.parse_args()

problem = cosserat.load_problem(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                              "cantilever_release.json"))
stepper = cosserat.Stepper(problem, spatial_scheme="heun" if args.heun else None)
summary = stepper.initialize_at_rest()  # under the problem's initial_loads: tip weight on
if not summary.converged:
    raise SystemExit(f"initial equilibrium: {summary.status}")

steps = int(round(args.seconds / stepper.dt))
t = np.empty(steps)
tip = np.empty((steps, 3))
shots = 0
start = time.perf_counter()
for k in range(steps):
    summary = stepper.step()  # under the problem's loads: the tip weight is gone
    if not summary.converged:
        raise SystemExit(f"step {k + 1}: {summary.status}")
    shots += summary.shots
    t[k] = stepper.time
    tip[k] = stepper.tip_position()
wall = time.perf_counter() - start

print(f"{steps} steps of {stepper.dt * 1e3:g} ms in {wall:.3f} s: {args.seconds / wall:.0f}x real "
      f"time, {shots / steps:.2f} shots per step")
print(f"tip x swings between {tip[:, 0].min() * 1e3:.2f} and {tip[:, 0].max() * 1e3:.2f} mm")
if args.plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 3))
    ax.plot(t, tip[:, 0] * 1e3)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("tip x (mm)")
    ax.set_title("Released cantilever (examples/cantilever_release.json)")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.plot)), exist_ok=True)
    fig.savefig(args.plot, dpi=120)
    print(f"wrote {args.plot}")
