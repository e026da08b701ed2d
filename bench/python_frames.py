#!/usr/bin/python3
"""What every node of every frame costs from Python: cosserat.solve of the peer release
(examples/cantilever_release.json) on 201 nodes for 10 s with a frame every 2 ms (5001 frames),
without and with nodes=True (out["frames"]["position"], 5001 x 201 x 3).

  PYTHONPATH=build/python /usr/bin/python3 bench/python_frames.py [--rounds 3]

Prints, per round (interleaved): wall seconds without and with nodes, their ratio, and the
Python heap's peak during the nodes=True call (tracemalloc).
"""
import argparse
import json
import os
import time
import tracemalloc

import cosserat

HERE = os.path.dirname(os.path.abspath(__file__))


def problem():
    with open(os.path.join(HERE, "..", "examples", "cantilever_release.json")) as f:
        spec = json.load(f)
    spec["rod"]["nodes"] = 201
    spec["dynamics"]["duration"] = 10.0
    spec["dynamics"]["output_interval"] = 0.002
    return spec


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=3)
    rounds = parser.parse_args().rounds
    spec = problem()
    for r in range(rounds):
        t0 = time.perf_counter()
        cosserat.solve(spec)
        plain = time.perf_counter() - t0
        tracemalloc.start()
        t0 = time.perf_counter()
        out = cosserat.solve(spec, nodes=True)
        with_nodes = time.perf_counter() - t0
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        shape = out["frames"]["position"].shape
        print(f"round {r}: without nodes {plain:.2f} s, with nodes {with_nodes:.2f} s "
              f"({with_nodes / plain:.1f}x), frames {shape}, Python peak {peak / 1e6:.0f} MB")


if __name__ == "__main__":
    main()
