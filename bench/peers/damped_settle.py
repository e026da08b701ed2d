#!/usr/bin/env python3
"""Time to settle on the soft cantilever (P2): a damped 5 s release, PyElastica against cosserat.

  /usr/bin/python3 bench/peers/damped_settle.py --elastica /work/peers/PyElastica \
      --cosserat /work/peers/cosserat-80b8d82 \
      --reference pe=REF_PE.csv se3=REF_SE3.csv qfd=REF_QFD.csv qfd-ll=REF_QFD_LL.csv \
      --out bench/peers/results/damped_settle.csv [--repeat 3] [--work /tmp/p2-settle]

The rod of bench/problems/soft_cantilever.json, clamped along +x, released straight under
gravity, run for --duration (5 s) with damping chosen so that it settles within the run. The two
codes damp differently:
  - PyElastica: AnalyticalLinearDamper, a uniform damping constant on the velocities
    (--pe-damping, 1/s; bench/peers/pyelastica_cantilever.py --damping);
  - cosserat: Kelvin-Voigt sectional damping (rod.material.damping), bending D = tau EI and
    torsion tau GJ with tau = --tau-bending (s). Two paths: "se3" (SE(3) shooting, BDF2, fixed
    dt) and "qfd" ("formulation": "quaternion-fd", Radau, integrator_tolerance). "qfd-ll" adds
    Lang & Linn's damping of extension and shear, tau_es EA and tau_es kappa GA
    (--tau-extension-shear, docs/quatfd.md).

Families and their configurations (each row one configuration):
  pe      ELEMENTS:DT   (--pe-configs); a blown-up run is a row and the step is halved
  se3     NODES:DT      (--se3-configs)
  qfd     NODES:TOL     (--qfd-configs)
  qfd-ll  NODES:TOL     (--qfd-ll-configs)
The families' runs alternate (round robin), so all see the same machine load.

Each row: the cost, median of --repeat runs of user + sys CPU of the whole process
(/usr/bin/time; cpu_s is the same from the kernel's rusage at microsecond resolution, since
/usr/bin/time rounds to 10 ms and the quaternion-FD runs take a few tens of ms). For PyElastica
also the stepping loop's CPU as the driver reports it (imports and numba compilation excluded:
loop_cpu_s): the cost to compare. The errors, % of L:
  err_ref_pct      largest tip distance over [0, duration] to the family's fine reference
                   (--reference NAME=CSV; the reference is interpolated onto the run's frames);
  final_to_static_pct   the final tip's distance to the same discretisation's static
                   equilibrium (cosserat: the "statics" analysis at the same nodes and
                   formulation; PyElastica: a long, more strongly damped run of the same
                   elements and dt, --pe-static-duration at --pe-static-damping);
  final_to_fine_static_pct  the final tip's distance to the code's converged equilibrium
                   (--fine-static NAME=X,Z: cosserat's SE(3) statics at 401 nodes, say).
"""
import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_tip_trajectories as ctt  # noqa: E402
from interleave import median, repeat_solve, run_interleaved, run_pyelastica, timed  # noqa: E402

BASE = os.path.join(HERE, "..", "problems", "soft_cantilever.json")
LENGTH = 0.3
E, G, R = 1.0e6, 1.0e6 / 3.0, 0.005
AREA = math.pi * R * R
I2 = math.pi * R ** 4 / 4.0
KAPPA = 0.9  # Cowper's shear coefficient for nu = 0.5 (6 (1 + nu) / (7 + 6 nu))





def cosserat_problem(path, nodes, args, qfd=False, tau_es=0.0, dt=None, tol=None, statics=False):
    with open(BASE) as f:
        p = json.load(f)
    p["rod"]["nodes"] = nodes
    damping = {"bending": args.tau_bending * E * I2, "torsion": args.tau_bending * G * 2.0 * I2}
    if tau_es > 0.0:
        damping["extension"] = tau_es * E * AREA
        damping["shear"] = tau_es * KAPPA * G * AREA
    p["rod"]["material"]["damping"] = damping
    if qfd:
        p["formulation"] = "quaternion-fd"
    if statics:
        p["analysis"] = "statics"
        p.pop("dynamics", None)
    else:
        d = p["dynamics"]
        d["duration"] = args.duration
        d["output_interval"] = args.output_interval
        if dt is not None:
            d["dt"] = dt
        else:  # quaternion-FD: dt is only the first step's size; the frames set the rest
            d["dt"] = min(d["dt"], args.output_interval)
        if tol is not None:
            d["integrator_tolerance"] = tol
    p["description"] = "damped_settle.py variant of soft_cantilever.json: %s, %d nodes%s%s%s, damping %s" % (
        "statics" if statics else "dynamics %g s" % args.duration, nodes,
        ", quaternion-fd" if qfd else "", "" if dt is None else ", dt %g" % dt,
        "" if tol is None else ", integrator_tolerance %g" % tol, json.dumps(damping))
    with open(path, "w") as f:
        json.dump(p, f, indent=2)


def dist(a, b):
    return math.sqrt(sum((u - v) ** 2 for u, v in zip(a, b)))


def parse_pairs(specs, conv):
    out = []
    for s in specs:
        a, b = s.split(":")
        out.append((int(a), conv(b)))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--elastica", required=True)
    ap.add_argument("--cosserat", required=True)
    ap.add_argument("--reference", nargs="+", required=True, help="FAMILY=CSV (pe, se3, qfd, qfd-ll)")
    ap.add_argument("--fine-static", nargs="*", default=[], help="FAMILY=X,Z: the converged static tip")
    ap.add_argument("--out", required=True)
    ap.add_argument("--work", default="/tmp/p2-settle")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--duration", type=float, default=5.0)
    ap.add_argument("--output-interval", type=float, default=0.01)
    ap.add_argument("--pe-damping", type=float, default=4.0)
    ap.add_argument("--pe-static-damping", type=float, default=8.0)
    ap.add_argument("--pe-static-duration", type=float, default=10.0)
    ap.add_argument("--tau-bending", type=float, default=0.5)
    ap.add_argument("--tau-extension-shear", type=float, default=1e-4)
    ap.add_argument("--pe-configs", nargs="*", default=["25:2e-4", "50:1e-4", "100:5e-5", "200:2.5e-5"])
    ap.add_argument("--se3-configs", nargs="*",
                    default=["%d:%g" % (n, dt) for n in (11, 21, 31, 51)
                             for dt in (0.01, 0.005, 0.002, 0.001, 0.0005)])
    ap.add_argument("--qfd-configs", nargs="*",
                    default=["%d:%g" % (n, t) for n in (11, 21, 31, 51, 101) for t in (1e-2, 1e-4, 1e-6)])
    ap.add_argument("--qfd-ll-configs", nargs="*",
                    default=["%d:%g" % (n, t) for n in (11, 21, 31, 51) for t in (1e-2, 1e-4)])
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)

    refs = {}
    for spec in args.reference:
        name, path = spec.split("=", 1)
        refs[name] = ctt.read_tip(path)[1]
    fine_static = {}
    for spec in args.fine_static:
        name, xz = spec.split("=", 1)
        x, z = (float(v) for v in xz.split(","))
        fine_static[name] = (x, 0.0, z)

    fields = ["code", "family", "configuration", "resolution", "dt_or_tol", "damping", "status", "failed_at_t",
              "cpu_s", "cpu_s_time", "loop_cpu_s", "wall_s", "steps", "runs",
              "err_ref_pct", "final_to_static_pct", "final_to_fine_static_pct", "final_tip_x", "final_tip_z"]
    rows = []

    def finish(row, csvp, static_tip):
        have = os.path.exists(csvp) and os.path.getsize(csvp) > 0
        fam = row["family"]
        if have:
            _, tr = ctt.read_tip(csvp)
            tip = tr[-1][1:]
            row["final_tip_x"], row["final_tip_z"] = round(tip[0], 8), round(tip[2], 8)
            if row["status"] in ("ok", "converged"):
                if fam in refs:
                    row["err_ref_pct"] = round(100.0 * ctt.max_distance(tr, refs[fam]) / LENGTH, 5)
                if static_tip is not None:
                    row["final_to_static_pct"] = round(100.0 * dist(tip, static_tip) / LENGTH, 5)
                if fam in fine_static:
                    row["final_to_fine_static_pct"] = round(100.0 * dist(tip, fine_static[fam]) / LENGTH, 5)
        return row

    def pe_jobs():
        for n, dt0 in parse_pairs(args.pe_configs, float):
            dt = dt0
            while dt > 1e-7:
                tag = "pe_%d_%g" % (n, dt)
                csvp = os.path.join(args.work, tag + ".csv")
                if os.path.exists(csvp):
                    os.remove(csvp)
                cpus, cputs, loops, walls = [], [], [], []
                for rep in range(args.repeat):
                    s, cput, cpu, wall = run_pyelastica(
                        args.elastica, n, dt, args.duration, csvp, "--damping",
                        repr(args.pe_damping), "--output-interval", repr(args.output_interval))
                    ok = s["finite"] == "yes"
                    cpus.append(cpu)
                    cputs.append(cput)
                    loops.append(s["cpu_s"])
                    walls.append(wall)
                    if not ok:
                        break
                    yield None
                static_tip = None
                if ok:  # the same rod settled: a longer run with stronger damping, untimed
                    sp = os.path.join(args.work, tag + "_static.csv")
                    settled, _, _, _ = run_pyelastica(
                        args.elastica, n, dt, args.pe_static_duration, sp, "--damping",
                        repr(args.pe_static_damping), "--output-interval", repr(args.pe_static_duration))
                    static_tip = tuple(settled["tip"])
                row = {"code": "pyelastica", "family": "pe", "configuration": "%d elements, dt %g" % (n, dt),
                       "resolution": n, "dt_or_tol": dt, "damping": "AnalyticalLinearDamper %g 1/s" % args.pe_damping,
                       "status": "ok" if ok else "blew_up", "failed_at_t": s["blew_up_at_t"],
                       "cpu_s": round(median(cpus), 4), "cpu_s_time": round(median(cputs), 3),
                       "loop_cpu_s": round(median(loops), 4), "wall_s": round(median(walls), 3),
                       "steps": s["steps"], "runs": len(cpus)}
                yield finish(row, csvp, static_tip)
                if ok:
                    break
                dt /= 2.0

    def ours_jobs(family, configs, qfd, tau_es, fixed_dt):
        statics = {}
        for n, v in configs:
            if n not in statics:
                sp = os.path.join(args.work, "%s_%d_static" % (family, n))
                cosserat_problem(sp + ".json", n, args, qfd=qfd, statics=True)
                code, _, err, _, _, _ = timed([args.cosserat, "solve", sp + ".json", "--out", sp + ".out.json"])
                with open(sp + ".out.json") as f:
                    r = json.load(f)
                statics[n] = tuple(r["tip"]["position"]) if r.get("status") == "converged" else None
            tag = "%s_%d_%g" % (family, n, v)
            prob = os.path.join(args.work, tag + ".json")
            cosserat_problem(prob, n, args, qfd=qfd, tau_es=tau_es,
                             dt=v if fixed_dt else None, tol=None if fixed_dt else v)
            csvp = os.path.join(args.work, tag + ".csv")
            resp = os.path.join(args.work, tag + ".out.json")
            for p in (csvp, resp):
                if os.path.exists(p):
                    os.remove(p)
            r, cputs, cpus, walls = yield from repeat_solve(args.cosserat, prob, resp, csvp,
                                                            args.repeat)
            damping = "Kelvin-Voigt tau_b %g s" % args.tau_bending + (", tau_es %g s" % tau_es if tau_es else "")
            row = {"code": "cosserat", "family": family,
                   "configuration": "%d nodes, %s %g" % (n, "dt" if fixed_dt else "tol", v),
                   "resolution": n, "dt_or_tol": v, "damping": damping,
                   "status": r["status"], "failed_at_t": r.get("failed_at_t"),
                   "cpu_s": round(median(cpus), 4), "cpu_s_time": round(median(cputs), 3), "loop_cpu_s": None,
                   "wall_s": round(median(walls), 3), "steps": r.get("steps"), "runs": len(cpus)}
            yield finish(row, csvp, statics[n])

    gens = [pe_jobs(),
            ours_jobs("se3", parse_pairs(args.se3_configs, float), False, 0.0, True),
            ours_jobs("qfd", parse_pairs(args.qfd_configs, float), True, 0.0, False),
            ours_jobs("qfd-ll", parse_pairs(args.qfd_ll_configs, float), True, args.tau_extension_shear, False)]
    run_interleaved(gens, rows, args.out, fields)

    # The coarsest (cheapest) configuration of each family within each accuracy level.
    cost = lambda r: r["loop_cpu_s"] if r["code"] == "pyelastica" else r["cpu_s"]  # noqa: E731
    best = {}
    for level in (1.0, 0.1):
        for fam in ("pe", "se3", "qfd", "qfd-ll"):
            ok = [r for r in rows if r["family"] == fam and r.get("err_ref_pct") is not None
                  and r["err_ref_pct"] <= level]
            if ok:
                best[(fam, level)] = min(ok, key=cost)
    print("\nlevel  family  configuration  cpu_s (pe: loop / process)  err_ref_pct")
    for (fam, level), r in sorted(best.items(), key=lambda kv: (-kv[0][1], kv[0][0])):
        print("%g %% L  %s  %s  %s  %s" % (level, fam, r["configuration"],
              "%s / %s" % (r["loop_cpu_s"], r["cpu_s"]) if fam == "pe" else r["cpu_s"], r["err_ref_pct"]))
    for level in (1.0, 0.1):
        pe = best.get(("pe", level))
        for fam in ("se3", "qfd", "qfd-ll"):
            c = best.get((fam, level))
            if pe and c:
                print("%g %% L: PyElastica / cosserat %s = %.1f (loop CPU), %.1f (process CPU)" % (
                    level, fam, pe["loop_cpu_s"] / c["cpu_s"], pe["cpu_s"] / c["cpu_s"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
