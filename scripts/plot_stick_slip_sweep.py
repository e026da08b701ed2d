#!/usr/bin/python3
"""Torsional stick-slip of a drill string against the rotary table's speed: runs `cosserat solve`
on a drill-string problem (default examples/drill_string_stick_slip.json) at each table speed,
measures the bit's spin over the last quarter of a 40 s run (its period from the upward crossings
of the table speed, its amplitude max − min, and whether the bit sticks: its spin falls below 2 %
of the table's), and plots them beside the one-degree-of-freedom
torsional pendulum J θ̈ = k (Ω t − θ) + T(θ̇) of the same string (k = GJ/L, J = J_BHA +
J_string/3, T the bit's friction torque), integrated here by RK4 at 0.2 ms.

Usage: plot_stick_slip_sweep.py [--problem P.json] [--cosserat EXE] [--out OUT.png] [--csv OUT.csv]
Uses Debian's python3-numpy and python3-matplotlib (run it with /usr/bin/python3).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SPEEDS = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0]  # rad/s


def bit_torque(bit, w):
    """The bit's friction torque T(ω) (N·m), as loads/bit_friction.hpp writes it."""
    wbar = math.sqrt(w * w + bit.get("regularisation", 1e-2) ** 2)
    mu_s, mu_k = bit["static_coefficient"], bit["kinetic_coefficient"]
    mu = mu_k + (mu_s - mu_k) * math.exp(-wbar / bit.get("stribeck_velocity", 1.0))
    return -bit.get("viscous", 0.0) * w - bit["weight_on_bit"] * bit["radius"] * mu * w / wbar


def pendulum(problem, speed, duration, dt=2e-4):
    """Spin history (t, θ̇) of the torsional pendulum at the table speed, from rest and unwound,
    as the rod starts."""
    rod = problem["rod"]
    sec, mat = rod["section"], rod["material"]
    ro, ri = sec["outer_radius"], sec["inner_radius"]
    polar = math.pi / 2 * (ro ** 4 - ri ** 4)
    k = mat["shear_modulus"] * polar / rod["length"]
    J = problem["dynamics"]["tip_inertia"][2] + mat["density"] * polar * rod["length"] / 3
    bit = problem["loads"]["bit_friction"]

    def rates(t, y):
        return np.array([y[1], (k * (speed * t - y[0]) + bit_torque(bit, y[1])) / J])

    y, t, out = np.zeros(2), 0.0, []
    steps = int(round(duration / dt))
    for i in range(steps):
        k1 = rates(t, y)
        k2 = rates(t + dt / 2, y + dt / 2 * k1)
        k3 = rates(t + dt / 2, y + dt / 2 * k2)
        k4 = rates(t + dt, y + dt * k3)
        y = y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += dt
        out.append((t, y[1]))
    return np.array(out)


def measure(t, spin, speed):
    """Period (mean spacing of upward crossings of the table speed), amplitude (max − min) and
    whether the bit sticks (its spin falls below 2 % of the table's), over the last quarter."""
    t, spin = np.asarray(t), np.asarray(spin)
    late = t >= 0.75 * t[-1]
    t, spin = t[late], spin[late]
    amplitude = spin.max() - spin.min()
    sticks = bool(spin.min() < 0.02 * speed)
    up = np.where((spin[:-1] < speed) & (spin[1:] >= speed))[0]
    if len(up) < 2:
        return float("nan"), amplitude, sticks
    crossings = t[up] + (speed - spin[up]) / (spin[up + 1] - spin[up]) * (t[up + 1] - t[up])
    return float(np.mean(np.diff(crossings))), amplitude, sticks


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--problem", default=os.path.join(here, "..", "examples",
                                                      "drill_string_stick_slip.json"))
    ap.add_argument("--cosserat", default=os.path.join(here, "..", "build", "apps", "cosserat"))
    ap.add_argument("--out", default="out/stick_slip_sweep.png")
    ap.add_argument("--csv", default="")
    args = ap.parse_args(argv[1:])
    with open(args.problem) as f:
        problem = json.load(f)
    duration = 40.0  # s: long enough for the start's transient to settle or lock into a cycle
    problem["dynamics"]["duration"] = duration
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for speed in SPEEDS:
            problem["dynamics"]["base_spin"] = speed
            src, dst = os.path.join(tmp, "p.json"), os.path.join(tmp, "r.json")
            with open(src, "w") as f:
                json.dump(problem, f)
            run = subprocess.run([args.cosserat, "solve", src, "--out", dst],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                sys.stderr.write(f"table speed {speed}: {run.stderr}")
                continue
            with open(dst) as f:
                traj = json.load(f)["trajectory"]
            rod_period, rod_amp, rod_sticks = measure(traj["t"], traj["tip_spin"], speed)
            pend = pendulum(problem, speed, duration)
            pend_period, pend_amp, pend_sticks = measure(pend[:, 0], pend[:, 1], speed)
            rows.append((speed, rod_period, rod_amp, int(rod_sticks), pend_period, pend_amp,
                         int(pend_sticks)))
            print(f"table {speed:4.1f} rad/s: rod period {rod_period:.4f} s, amplitude "
                  f"{rod_amp:.4f} rad/s, sticks {rod_sticks}; pendulum {pend_period:.4f} s, "
                  f"{pend_amp:.4f} rad/s, sticks {pend_sticks}")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("table_speed,rod_period,rod_amplitude,rod_sticks,pendulum_period,"
                    "pendulum_amplitude,pendulum_sticks\n")
            for r in rows:
                f.write(",".join(f"{v:.6g}" for v in r) + "\n")
    data = np.array(rows)
    stick = data[:, 3] > 0
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for ax, col, label in ((axes[0], 1, "period [s]"), (axes[1], 2, "spin amplitude [rad/s]")):
        ax.plot(data[:, 0], data[:, col + 3], "k--", label="torsional pendulum")
        ax.plot(data[stick, 0], data[stick, col], "o", color="C3", label="rod: stick-slip")
        ax.plot(data[~stick, 0], data[~stick, col], "o", mfc="none", color="C0",
                label="rod: no sticking (a decaying swing)")
        ax.set_xlabel("table speed [rad/s]")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("torsional stick-slip against the table speed, from rest (last 10 of 40 s)")
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    fig.savefig(args.out, dpi=120)
    print(f"plot written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
