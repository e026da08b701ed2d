#!/usr/bin/env python3
"""PyElastica side of the soft-cantilever peer benchmark (P2, bench/problems/soft_cantilever.json).

Silicone cantilever: L = 0.3 m, circular section r = 5 mm, E = 1 MPa, G = E/3 (Poisson 0.5),
rho = 1100 kg/m^3, clamped at s = 0 along +x, gravity 9.81 m/s^2 along -z, released straight and
at rest at t = 0, undamped unless --damping is given.

PyElastica's rod has N elements between N + 1 nodes; positions are node positions.
Run with Debian's interpreter (bench/peers/install-peer-deps.sh):

  /usr/bin/python3 bench/peers/pyelastica_cantilever.py --elastica /work/peers/PyElastica \
      --elements 400 --dt 1e-5 --duration 1 --out tip.csv

Output CSV: header "t,x,y,z" (the tip node), or with --all-nodes the long format of cosserat's
trajectory table, "t,node,s,x,y,z" (s the rest arc length of the node). One frame every
--output-interval (rounded to a whole number of steps).

Timing: numba compiles PyElastica's kernels on first use. A throwaway copy of the rod is stepped
--warmup-steps times first (compile_s); then the real run is timed, wall (perf_counter) and
process CPU (process_time), over the stepping loop only (the frame copies included, the CSV
writing not). Prints one JSON line to stdout.
"""
import argparse
import json
import math
import os
import sys
import time

# One thread, like the cosserat binary (numpy's BLAS is barely used here anyway).
for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

LENGTH = 0.3
RADIUS = 0.005
YOUNGS = 1.0e6
SHEAR = YOUNGS / 3.0  # Poisson 0.5: G = E / (2 (1 + 0.5))
DENSITY = 1100.0
GRAVITY = 9.81
BLOWUP_REACH = 1.1


def build(ea, np, n_elements, dt, damping, inertia_scale=1.0, shear_scale=1.0):
    class Sim(ea.BaseSystemCollection, ea.Constraints, ea.Forcing, ea.Damping):
        pass

    sim = Sim()
    rod = ea.CosseratRod.straight_rod(
        n_elements,
        np.zeros(3),                 # start
        np.array([1.0, 0.0, 0.0]),   # direction: the clamp's axis, +x
        np.array([0.0, 0.0, 1.0]),   # normal (d1); circular section, so any normal will do
        LENGTH,
        RADIUS,
        DENSITY,
        youngs_modulus=YOUNGS,
        shear_modulus=SHEAR,
    )
    if inertia_scale != 1.0:  # diagnostic: how much the rotational inertia matters
        rod.mass_second_moment_of_inertia *= inertia_scale
        rod.inv_mass_second_moment_of_inertia /= inertia_scale
    if shear_scale != 1.0:  # diagnostic: PyElastica's shear stiffness is (27/28) G A
        rod.shear_matrix[0, 0, :] *= shear_scale
        rod.shear_matrix[1, 1, :] *= shear_scale
    sim.append(rod)
    sim.constrain(rod).using(
        ea.OneEndFixedBC, constrained_position_idx=(0,), constrained_director_idx=(0,)
    )
    sim.add_forcing_to(rod).using(ea.GravityForces, acc_gravity=np.array([0.0, 0.0, -GRAVITY]))
    if damping is not None and damping > 0.0:
        sim.dampen(rod).using(
            ea.AnalyticalLinearDamper, uniform_damping_constant=damping, time_step=dt
        )
    sim.finalize()
    return sim, rod


def patch_bending_law(np):
    """Diagnostic: PyElastica's couple is B kappa / e^3 (e the Voronoi dilatation; Gazzola et al.
    2018 scale the section with the stretch of an incompressible rod). This wraps the torque
    kernel (looked up as a module global by CosseratRod.compute_internal_forces_and_torques) so
    that it sees e = 1 there, which leaves B kappa, cosserat's linear law. The dilatation still
    enters the inertia terms; PyElastica's own code is not changed."""
    import elastica.rod.cosserat_rod as cr

    torques = cr._compute_internal_torques

    def linear_torques(*a):
        a = list(a)
        a[10] = np.ones_like(a[10])  # voronoi_dilatation: used only for the e^-3 factor
        torques(*a)

    cr._compute_internal_torques = linear_torques


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--elastica", required=True, help="PyElastica source directory (holds elastica/)")
    ap.add_argument("--elements", type=int, required=True)
    ap.add_argument("--dt", type=float, required=True)
    ap.add_argument("--duration", type=float, default=1.0)
    ap.add_argument("--damping", type=float, default=None,
                    help="AnalyticalLinearDamper uniform_damping_constant, 1/s (default: undamped)")
    ap.add_argument("--output-interval", type=float, default=1e-3)
    ap.add_argument("--all-nodes", action="store_true", help="write every node (t,node,s,x,y,z)")
    ap.add_argument("--warmup-steps", type=int, default=20)
    ap.add_argument("--out", default=None, help="CSV file (default: none)")
    ap.add_argument("--linear-bending-law", action="store_true",
                    help="diagnostic: PyElastica's couple is B kappa / e^3 (e the Voronoi dilatation, "
                         "Gazzola et al. 2018); with this flag it is B kappa, the linear law of cosserat")
    ap.add_argument("--rotational-inertia-scale", type=float, default=1.0,
                    help="diagnostic: multiply the elements' mass second moments of inertia")
    ap.add_argument("--shear-stiffness-scale", type=float, default=1.0,
                    help="diagnostic: multiply the two shear stiffnesses (e.g. 0.9*28/27 for cosserat's Cowper 0.9)")
    args = ap.parse_args()

    sys.path.insert(0, os.path.abspath(args.elastica))
    t_import = time.perf_counter()
    import numpy as np
    import elastica as ea
    import_s = time.perf_counter() - t_import

    if args.linear_bending_law:
        patch_bending_law(np)

    n = args.elements
    dt = args.dt
    steps = int(round(args.duration / dt))
    every = max(1, int(round(args.output_interval / dt)))

    # JIT warm-up on a throwaway rod of the same size (numba specialises on types, not sizes).
    t0 = time.perf_counter()
    wsim, _ = build(ea, np, n, dt, args.damping, args.rotational_inertia_scale, args.shear_stiffness_scale)
    stepper = ea.PositionVerlet()
    tw = 0.0
    for _ in range(args.warmup_steps):
        tw = stepper.step(wsim, tw, dt)
    compile_s = time.perf_counter() - t0
    del wsim

    sim, rod = build(ea, np, n, dt, args.damping, args.rotational_inertia_scale, args.shear_stiffness_scale)
    stepper = ea.PositionVerlet()
    pos = rod.position_collection  # (3, n + 1), updated in place

    frames_t = [0.0]
    frames_x = [pos.copy() if args.all_nodes else pos[:, -1].copy()]
    finite = True
    blew_up_at = None
    t = np.float64(0.0)
    done = 0
    w0 = time.perf_counter()
    c0 = time.process_time()
    while done < steps:
        k = min(every, steps - done)
        for _ in range(k):
            t = stepper.step(sim, t, dt)
        done += k
        tip = pos[:, -1]
        # Blown up: not finite, or the tip farther from the clamp than 1.1 L (the rod's static
        # stretch under its weight is ~0.3 %; an unstable step grows without bound).
        if not (np.all(np.isfinite(tip)) and float(np.sqrt(tip @ tip)) < BLOWUP_REACH * LENGTH):
            finite = False
            blew_up_at = done * dt
            break
        frames_t.append(done * dt)
        frames_x.append(pos.copy() if args.all_nodes else tip.copy())
    wall = time.perf_counter() - w0
    cpu = time.process_time() - c0
    if finite:
        finite = bool(np.all(np.isfinite(pos)))

    if args.out:
        with open(args.out, "w") as f:
            if args.all_nodes:
                f.write("t,node,s,x,y,z\n")
                s = np.linspace(0.0, LENGTH, n + 1)
                for tt, p in zip(frames_t, frames_x):
                    for i in range(n + 1):
                        f.write("%.9g,%d,%.9g,%.17g,%.17g,%.17g\n" % (tt, i, s[i], p[0, i], p[1, i], p[2, i]))
            else:
                f.write("t,x,y,z\n")
                for tt, p in zip(frames_t, frames_x):
                    f.write("%.9g,%.17g,%.17g,%.17g\n" % (tt, p[0], p[1], p[2]))

    sim_time = done * dt
    summary = {
        "code": "pyelastica",
        "elements": n,
        "nodes": n + 1,
        "dt": dt,
        "steps": done,
        "simulated_s": sim_time,
        "damping": args.damping,
        "rotational_inertia_scale": args.rotational_inertia_scale,
        "shear_stiffness_scale": args.shear_stiffness_scale,
        "linear_bending_law": args.linear_bending_law,
        "import_s": round(import_s, 3),
        "compile_s": round(compile_s, 3),
        "wall_s": round(wall, 4),
        "cpu_s": round(cpu, 4),
        "us_per_step": round(1e6 * wall / max(done, 1), 3),
        "cpu_per_simulated_s": round(cpu / sim_time, 4) if sim_time > 0 else None,
        "real_time_ratio": round(sim_time / wall, 5) if wall > 0 else None,
        "finite": "yes" if finite else "no",
        "blew_up_at_t": blew_up_at,
        "tip": [float(v) for v in pos[:, -1]],
    }
    print(json.dumps(summary))
    return 0 if finite else 1


if __name__ == "__main__":
    sys.exit(main())
