#!/usr/bin/env python3
"""Writes the continuum Stewart-Gough robot (Bryson & Rucker 2014; Till, Aloi & Rucker 2019) as a
problem file, the robot exactly as ContinuumStewartGough() builds it
(src/robots/stewart_gough.cpp): six spring-steel rods through torsion-free holes of a base plate,
clamped to a platform, the platform starting at z = 0.4 m.

  make_stewart_gough.py                  robots/stewart_gough.json: inverse kinematics of the
                                         platform at (0, 0.02, 0.45) m, turned 0.1 rad about z
  make_stewart_gough.py --lengths L1..L6 robots/stewart_gough_forward.json: forward kinematics
                                         at these rod lengths (m)
"""
import argparse
import json
import math
import pathlib

ROOT = pathlib.Path(__file__).resolve().parent.parent

# StewartGoughParameters' defaults (include/cosserat/robots/stewart_gough.hpp).
E, NU, RHO = 207e9, 0.305, 8000.0  # Pa, -, kg/m^3
ROD_RADIUS, CIRCLE_RADIUS = 0.00065, 0.087  # m
ALPHA = 100.0 * math.pi / 180.0  # rad
LENGTH, NODES = 0.4, 40  # m, grid points


def holes():
    """The angles of the base's and the platform's hole i (rad), as the builder computes them."""
    a1, a2 = ALPHA, 2.0 * math.pi / 3.0 - ALPHA
    out = []
    for i in range(6):
        theta_b = (-a2 + ((i + 1) - (i + 1) % 2) * a2 + (i - i % 2) * a1) / 2
        theta_p = (-a1 + ((i + 1) - (i + 1) % 2) * a1 + (i - i % 2) * a2) / 2
        out.append((theta_b, theta_p))
    return out


def on_circle(theta):
    return [CIRCLE_RADIUS * math.cos(theta), CIRCLE_RADIUS * math.sin(theta), 0.0]


def problem(lengths):
    identity = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    rods = []
    for i, (theta_b, theta_p) in enumerate(holes()):
        rods.append({
            "name": f"rod{i + 1}",
            "rod": {"length": LENGTH, "nodes": NODES,
                    "section": {"shape": "circle", "radius": ROD_RADIUS},
                    "material": {"youngs_modulus": E, "poisson_ratio": NU, "density": RHO}},
            "base": {"position": on_circle(theta_b), "rotation": identity,
                     "joint": "torsion_free"},
            "tip": {"joint": "clamped", "body": "platform",
                    "attachment": {"position": on_circle(theta_p), "rotation": identity}},
        })
    assembly = {
        "rods": rods,
        "bodies": [{"name": "platform", "mass": 0.0,
                    "pose": {"position": [0.0, 0.0, LENGTH], "rotation": identity}}],
    }
    if lengths:
        assembly["lengths"] = lengths
        what = "forward kinematics: the platform's pose for the rods' lengths"
    else:
        c, s = math.cos(0.1), math.sin(0.1)
        assembly["inverse"] = {"poses": [{"body": "platform", "position": [0.0, 0.02, 0.45],
                                          "rotation": [[c, -s, 0], [s, c, 0], [0, 0, 1]]}]}
        what = ("inverse kinematics: the rods' lengths that hold the platform at (0, 0.02, 0.45) m, "
                "turned 0.1 rad about z")
    return {
        "format": "cosserat-problem/1",
        "description": "Continuum Stewart-Gough robot (Bryson & Rucker 2014; the example of Till, "
                       "Aloi & Rucker 2019): six spring-steel rods (r = 0.65 mm) pass through "
                       "torsion-free holes on a 87 mm circle of the base plate and are clamped to "
                       "the platform's holes; " + what + ", under the rods' weight. Written by "
                       "scripts/make_stewart_gough.py.",
        "analysis": "statics",
        "formulation": "se3-shooting",
        "loads": {"gravity": [0, 0, -9.81]},
        "assembly": assembly,
    }


def dump(value, indent=0):
    """JSON with arrays of numbers (and of such arrays) on one line."""
    pad = "  " * indent
    flat = json.dumps(value)
    if not isinstance(value, (dict, list)) or len(flat) <= 100 - len(pad) and (
            isinstance(value, list) or not any(isinstance(v, (dict, list)) for v in value.values())):
        return flat
    if isinstance(value, list):
        items = [pad + "  " + dump(v, indent + 1) for v in value]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    items = [pad + "  " + json.dumps(k) + ": " + dump(v, indent + 1) for k, v in value.items()]
    return "{\n" + ",\n".join(items) + "\n" + pad + "}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lengths", type=float, nargs=6, help="rod lengths, m (forward problem)")
    args = parser.parse_args()
    name = "stewart_gough_forward.json" if args.lengths else "stewart_gough.json"
    path = ROOT / "robots" / name
    path.write_text(dump(problem(args.lengths)) + "\n", encoding="utf-8")
    print(path)


if __name__ == "__main__":
    main()
