#!/usr/bin/env python3
"""Accuracy against cost on the soft cantilever (P2), PyElastica and cosserat interleaved.

  /usr/bin/python3 bench/peers/accuracy_cost.py --elastica /work/peers/PyElastica \
      --cosserat /work/peers/cosserat-6511edf --reference NAME=REF.csv [NAME=REF.csv ...] \
      --out bench/peers/results/accuracy_cost.csv [--until 0.3 0.5 1.0] [--repeat 3] [--work /tmp/p2-table]

PyElastica: for each element count (--elements, default 25 50 100 200) the time step is halved
from --dt-start (2e-4) until a 1 s run stays bounded (bench/peers/pyelastica_cantilever.py's
test); each blown-up step is a row too. cosserat: every --nodes x --dts x --schemes
(default 11 21 31 51 x 5 2 1 ms x rk4 heun) on bench/problems/soft_cantilever.json.
The two codes' runs alternate, so both see the same machine load.

Each row: the error, the maximum tip distance to each reference over [0, until] / L for each
--until (err_NAME_until_U), and the cost: process CPU seconds (user + sys, /usr/bin/time) per
simulated second, the median of --repeat runs. For PyElastica the stepping loop's CPU (numba
compilation and imports excluded: loop_cpu_s_per_sim_s) is the cost to compare; its process CPU
adds ~2-15 s of imports and JIT. For cosserat the process CPU is the whole run (start, initial
equilibrium, stepping, writing the frames).
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_tip_trajectories as ctt  # noqa: E402
from interleave import median, repeat_solve, run_interleaved, run_pyelastica  # noqa: E402

DURATION = 1.0


def errors(ref, path, untils, length):
    """Max tip distance / L over the run's own frames in [0, until] for each until (None when
    the run or the reference ends before it); the (denser) reference is interpolated onto them."""
    _, run = ctt.read_tip(path)
    t_end = min(run[-1][0], ref[-1][0])
    return [None if t_end < u - 1e-9 else ctt.max_distance(run, ref, u) / length for u in untils]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--elastica", required=True)
    ap.add_argument("--cosserat", required=True)
    ap.add_argument("--reference", required=True, nargs="+",
                    help="NAME=PATH: tip trajectory CSVs (either format), 1 ms frames")
    ap.add_argument("--repeat", type=int, default=3, help="runs per configuration for the timing")
    ap.add_argument("--out", required=True)
    ap.add_argument("--work", default="/tmp/p2-table")
    ap.add_argument("--until", type=float, nargs="+", default=[0.3, 0.5, 1.0])
    ap.add_argument("--length", type=float, default=0.3)
    ap.add_argument("--elements", type=int, nargs="+", default=[25, 50, 100, 200])
    ap.add_argument("--dt-start", type=float, default=2e-4)
    ap.add_argument("--dt-min", type=float, default=1e-6)
    ap.add_argument("--nodes", type=int, nargs="+", default=[11, 21, 31, 51])
    ap.add_argument("--dts", type=float, nargs="+", default=[0.005, 0.002, 0.001])
    ap.add_argument("--schemes", nargs="+", default=["rk4", "heun"])
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)

    refs = []
    for spec in args.reference:
        name, path = spec.split("=", 1)
        refs.append((name, ctt.read_tip(path)[1]))
    err_fields = ["err_%s_until_%g" % (name, u) for name, _ in refs for u in args.until]
    fields = ["code", "resolution", "dt", "scheme", "status", "blew_up_at_t"] + err_fields + \
             ["cpu_s_per_sim_s", "loop_cpu_s_per_sim_s", "wall_s", "steps", "runs"]

    def fill_errors(row, csvp):
        # A run that failed or blew up still has its frames up to then: windows it covered count.
        have = os.path.exists(csvp) and os.path.getsize(csvp) > 0
        for name, ref in refs:
            errs = errors(ref, csvp, args.until, args.length) if have else [None] * len(args.until)
            for u, e in zip(args.until, errs):
                row["err_%s_until_%g" % (name, u)] = None if e is None else round(e, 6)
    rows = []

    def pe_jobs():
        for n in args.elements:
            dt = args.dt_start
            while dt >= args.dt_min:
                csvp = os.path.join(args.work, "pe_%d_%g.csv" % (n, dt))
                if os.path.exists(csvp):
                    os.remove(csvp)
                cpus, loops, walls = [], [], []
                for rep in range(args.repeat):
                    s, cpu, _, wall = run_pyelastica(args.elastica, n, dt, DURATION, csvp)
                    ok = s["finite"] == "yes"
                    cpus.append(cpu)
                    loops.append(s["cpu_s"] / s["simulated_s"] if s["simulated_s"] > 0 else float("nan"))
                    walls.append(wall)
                    if not ok:
                        break  # a blown-up step is not timed again
                    if rep + 1 < args.repeat:
                        yield None  # let the other code run in between
                row = {"code": "pyelastica", "resolution": "%d elements" % n, "dt": dt, "scheme": "position-verlet",
                       "status": "ok" if ok else "blew_up", "blew_up_at_t": s["blew_up_at_t"],
                       "cpu_s_per_sim_s": round(median(cpus) / DURATION, 4),
                       "loop_cpu_s_per_sim_s": round(median(loops), 4),
                       "wall_s": round(median(walls), 3), "steps": s["steps"], "runs": len(cpus)}
                fill_errors(row, csvp)
                yield row
                if ok:
                    break
                dt /= 2.0

    def ours_jobs():
        for scheme in args.schemes:
            for n in args.nodes:
                for dt in args.dts:
                    name = "c_%d_%g_%s" % (n, dt, scheme)
                    prob = os.path.join(args.work, name + ".json")
                    subprocess.run([sys.executable, os.path.join(HERE, "soft_cantilever_variant.py"), prob,
                                    "--nodes", str(n), "--dt", repr(dt), "--duration", repr(DURATION),
                                    "--output-interval", repr(dt), "--scheme", scheme], check=True)
                    csvp = os.path.join(args.work, name + ".csv")
                    if os.path.exists(csvp):
                        os.remove(csvp)
                    resp = os.path.join(args.work, name + ".out.json")
                    r, cpus, _, walls = yield from repeat_solve(args.cosserat, prob, resp, csvp,
                                                                args.repeat)
                    row = {"code": "cosserat", "resolution": "%d nodes" % n, "dt": dt, "scheme": scheme,
                           "status": r["status"], "blew_up_at_t": r.get("failed_at_t"),
                           "cpu_s_per_sim_s": round(median(cpus) / DURATION, 4), "loop_cpu_s_per_sim_s": None,
                           "wall_s": round(median(walls), 3), "steps": r["steps"], "runs": len(cpus)}
                    fill_errors(row, csvp)
                    yield row

    gens = [pe_jobs(), ours_jobs()]
    run_interleaved(gens, rows, args.out, fields)
    return 0


if __name__ == "__main__":
    sys.exit(main())
