#!/usr/bin/python3
"""The batched Python stepper against one rod after another: 64 rods of the peer release's wire
(examples/cantilever_release.json), 200 steps each, every rod its own tip force per step.

  PYTHONPATH=build/python /usr/bin/python3 bench/batch_stepper.py [--rounds 3]

Prints, per round (interleaved): 64 cosserat.Stepper objects stepped one after another from
Python, a BatchStepper on 1 thread, and on 2 threads; wall time per batch step and the ratios.
"""
import argparse
import time

import numpy as np

import cosserat

M, STEPS = 64, 200


def forces(k):
    return np.array([[-0.01 * (i % 8), 1e-3 * (k % 50) * (i % 3), 0.0] for i in range(M)])


def lone(p):
    steppers = [cosserat.Stepper(p) for _ in range(M)]
    for s in steppers:
        s.initialize_at_rest()
    loads = [s.loads for s in steppers]
    t0 = time.perf_counter()
    for k in range(STEPS):
        f = forces(k)
        for i, s in enumerate(steppers):
            loads[i].tip_force = f[i]
            s.step(loads=loads[i])
    return (time.perf_counter() - t0) / STEPS


def batch(p, threads):
    b = cosserat.BatchStepper(p, M, threads=threads)
    b.initialize_at_rest()
    t0 = time.perf_counter()
    for k in range(STEPS):
        b.step(tip_force=forces(k))
    return (time.perf_counter() - t0) / STEPS


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args()
    p = cosserat.load_problem("examples/cantilever_release.json")
    for r in range(args.rounds):
        t_lone, t1, t2 = lone(p), batch(p, 1), batch(p, 2)
        print(f"round {r}: one after another {1e3 * t_lone:.2f} ms, batch 1 thread {1e3 * t1:.2f} ms, "
              f"2 threads {1e3 * t2:.2f} ms per step of {M} rods: 2 threads vs one after another "
              f"{t_lone / t2:.2f}x, vs 1 thread {t1 / t2:.2f}x", flush=True)


if __name__ == "__main__":
    main()
