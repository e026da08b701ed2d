#!/usr/bin/env python3
"""Where statics with a stiff contact foundation stops converging, in both formulations.

Runs examples/rod_on_table.json (a 2.5 m steel rod lying down on a Winkler floor) through
`cosserat solve` for each foundation stiffness k (N/m per m) and grid size, in the SE(3) shooting
and the quaternion-FD formulations, and prints one row per case: status, touchdown point (the
first node in contact), the CPU time of the process and the shooting exponent (k/EI)^(1/4) L.

    python3 bench/contact_convergence_map.py --cosserat build/apps/cosserat \
        --stiffness 1e3 1e5 1e7 1e9 --nodes 51 101 251 501
"""
import argparse
import json
import math
import os
import resource
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "examples", "rod_on_table.json")


def run(binary, problem, workdir, tag):
    path = os.path.join(workdir, tag + ".json")
    out = os.path.join(workdir, tag + ".out.json")
    with open(path, "w") as f:
        json.dump(problem, f)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run([binary, "solve", path, "--out", out], capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if not os.path.exists(out):
        return {"status": "error: " + (proc.stderr.strip().splitlines() or ["?"])[-1]}, cpu
    with open(out) as f:
        return json.load(f), cpu


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--cosserat", default="build/apps/cosserat")
    ap.add_argument("--stiffness", type=float, nargs="+", default=[1e3, 1e5, 1e7, 1e9])
    ap.add_argument("--nodes", type=int, nargs="+", default=[51, 101, 251, 501])
    ap.add_argument("--formulations", nargs="+", default=["se3-shooting", "quaternion-fd"])
    args = ap.parse_args()
    with open(EXAMPLE) as f:
        base = json.load(f)
    r = base["rod"]["section"]["radius"]
    EI = base["rod"]["material"]["youngs_modulus"] * math.pi * r ** 4 / 4
    L = base["rod"]["length"]
    print("| formulation | k (N/m²) | nodes | (k/EI)^¼ L | status | touchdown s (m) | CPU s |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for formulation in args.formulations:
            for k in args.stiffness:
                for n in args.nodes:
                    p = json.loads(json.dumps(base))
                    p["formulation"] = formulation
                    p["rod"]["nodes"] = n
                    p["environment"]["contact"][0]["stiffness"] = k
                    res, cpu = run(args.cosserat, p, work, f"{formulation}_{k:g}_{n}")
                    status = res.get("status", "?")
                    if isinstance(status, dict):
                        status = status.get("status", json.dumps(status))
                    intervals = res.get("contact", {}).get("intervals", [])
                    touchdown = f"{intervals[0][0]:.4f}" if intervals else "–"
                    exponent = (k / EI) ** 0.25 * L
                    print(f"| {formulation} | {k:.0e} | {n} | {exponent:.0f} | {status} | "
                          f"{touchdown} | {cpu:.2f} |", flush=True)


if __name__ == "__main__":
    main()
