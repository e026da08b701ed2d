#!/usr/bin/env python3
"""Writes a variant of bench/problems/soft_cantilever.json for the peer benchmark.

  soft_cantilever_variant.py OUT.json [--nodes N] [--dt DT] [--duration T]
      [--output-interval DT_OUT] [--scheme rk4|heun] [--segments K] [--statics]
      [--tolerance TOL]

--statics writes the static problem of the same rod (the hanging equilibrium under gravity).
"""
import argparse
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
BASE = os.path.join(HERE, "..", "problems", "soft_cantilever.json")

ap = argparse.ArgumentParser()
ap.add_argument("out")
ap.add_argument("--base", default=BASE)
ap.add_argument("--nodes", type=int)
ap.add_argument("--dt", type=float)
ap.add_argument("--duration", type=float)
ap.add_argument("--output-interval", type=float)
ap.add_argument("--scheme", choices=["rk4", "heun"])
ap.add_argument("--segments", type=int)
ap.add_argument("--tolerance", type=float)
ap.add_argument("--statics", action="store_true")
a = ap.parse_args()

with open(a.base) as f:
    p = json.load(f)
desc = []
if a.nodes:
    p["rod"]["nodes"] = a.nodes
    desc.append("nodes %d" % a.nodes)
if a.statics:
    p["analysis"] = "statics"
    p.pop("dynamics", None)
    desc.append("statics")
else:
    d = p["dynamics"]
    for key, val in (("dt", a.dt), ("duration", a.duration), ("output_interval", a.output_interval),
                     ("spatial_scheme", a.scheme), ("shooting_segments", a.segments)):
        if val is not None:
            d[key] = val
            desc.append("%s %s" % (key, val))
if a.tolerance:
    p.setdefault("solver", {})["tolerance"] = a.tolerance
p["description"] = "Variant of soft_cantilever.json for the peer benchmark: " + ", ".join(desc)
with open(a.out, "w") as f:
    json.dump(p, f, indent=2)
