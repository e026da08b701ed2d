#!/usr/bin/python3
"""The VTK time series of `cosserat solve --vtk`, read back with the VTK library (Debian's
python3-vtk9), against the JSON result of the same run.

  test_vtk_series.py COSSERAT_BINARY PROBLEM.json [--formulation quaternion-fd]

For a 2 s dynamics run: the .pvd lists every frame of the result's trajectory with its time;
every frame's last point is the trajectory's tip position and the last frame's points are the
result's final nodes, to 1e-12 m (both are written with 17 significant digits, so the doubles
come back exactly; 1e-12 leaves room for nothing but the text round trip); the last frame's
directors at the tip are the columns of the result's tip rotation and its internal force at the
clamp is the negative of the result's base reaction, to 1e-12 (with contact surfaces, the contact force
per node is the result's, to 1e-12 relative); the directors are orthonormal to
1e-2 (the quaternion-FD path's rotations are exact; the SE(3) path's RK4 keeps R a rotation to
its truncation, which near this soft rod's clamp, at h κ ≈ 1.2, measures 1.5e-3). A file the
test cannot read fails it.
"""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def run(binary, problem, formulation, work):
    with open(problem) as f:
        spec = json.load(f)
    if formulation:
        spec["formulation"] = formulation
    path = os.path.join(work, "run.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    out = os.path.join(work, "result.json")
    vtk_dir = os.path.join(work, "vtk")
    p = subprocess.run([binary, "solve", path, "--out", out, "--vtk", vtk_dir],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit(f"cosserat failed ({p.returncode}):\n{p.stderr}")
    with open(out) as f:
        return spec, json.load(f), os.path.join(vtk_dir, "run.pvd")


def read_frame(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        sys.exit(f"{path}: VTK read no points")
    points = vtk_to_numpy(data.GetPoints().GetData())
    arrays = {}
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arrays[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i))
    return points, arrays, data.GetNumberOfLines()


def main(argv):
    binary, problem = argv[1], argv[2]
    formulation = argv[4] if len(argv) > 4 and argv[3] == "--formulation" else None
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    with tempfile.TemporaryDirectory() as work:
        spec, result, pvd = run(binary, problem, formulation, work)
        if "assembly" in result:  # each rod's points carry its index, as in assembly.rods
            datasets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
            points, arrays, lines = read_frame(os.path.join(os.path.dirname(pvd),
                                                            datasets[-1].get("file")))
            rods = result["assembly"]["rods"]
            check(lines == len(rods), f"{lines} polylines for {len(rods)} rods")
            start = 0
            for r, rod in enumerate(rods):
                nodes = np.asarray(rod["nodes"]["position"])
                mine = arrays["rod"][start:start + len(nodes)]
                check(np.all(mine == r), f"rod {r}'s points are labelled {set(mine.tolist())}")
                gap = np.abs(points[start:start + len(nodes)] - nodes).max()
                check(gap < 1e-12, f"rod {r}'s last frame differs from its nodes by {gap} m")
                start += len(nodes)
            # The bodies: a series of their own, one vertex each, at the result's final poses.
            body_pvd = pvd[:-len(".pvd")] + "_bodies.pvd"
            body_sets = ET.parse(body_pvd).getroot().find("Collection").findall("DataSet")
            check(len(body_sets) == len(datasets), "the bodies' series has another frame count")
            bpoints, barrays, _ = read_frame(os.path.join(os.path.dirname(pvd),
                                                          body_sets[-1].get("file")))
            for b, body in enumerate(result["assembly"]["bodies"]):
                gap = np.abs(bpoints[b] - np.asarray(body["position"])).max()
                check(gap < 1e-12 and barrays["body"][b] == b,
                      f"body {b} at {bpoints[b]}, the result has {body['position']}")
            print(f"assembly: {len(rods)} rods labelled, {len(datasets)} frames, "
                  f"{len(result['assembly']['bodies'])} bodies")
            for f in failures:
                print("FAIL:", f)
            return 1 if failures else 0
        if "trajectory" not in result:  # statics: the equilibrium, one frame at t = 0
            datasets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
            check(len(datasets) == 1 and float(datasets[0].get("timestep")) == 0.0,
                  f"a static answer is one frame at t = 0, got {len(datasets)}")
            points, arrays, _ = read_frame(os.path.join(os.path.dirname(pvd),
                                                        datasets[0].get("file")))
            nodes = np.asarray(result["nodes"]["position"])
            final = np.abs(points - nodes).max()
            check(points.shape == nodes.shape and final < 1e-12,
                  f"the frame's points differ from the result's nodes by {final} m")
            reaction = np.asarray(result["base_wrench"]["force"])
            check(np.abs(arrays["force"][0] + reaction).max() < 1e-12 * max(1, abs(reaction).max()),
                  "the clamp's internal force is not minus the reaction")
            print(f"statics: 1 frame, nodes {final:.1e} m")
            for f in failures:
                print("FAIL:", f)
            return 1 if failures else 0
        traj = result["trajectory"]
        datasets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
        check(len(datasets) == len(traj["t"]),
              f".pvd lists {len(datasets)} frames, the trajectory has {len(traj['t'])}")
        worst_tip = worst_time = 0.0
        last = None
        for k, ds in enumerate(datasets):
            worst_time = max(worst_time, abs(float(ds.get("timestep")) - traj["t"][k]))
            points, arrays, lines = read_frame(os.path.join(os.path.dirname(pvd), ds.get("file")))
            check(lines == 1, f"frame {k}: {lines} polylines, expected 1")
            worst_tip = max(worst_tip, np.abs(points[-1] - traj["tip_position"][k]).max())
            last = (points, arrays)
        check(worst_time < 1e-12, f"frame times differ from the trajectory's by {worst_time}")
        check(worst_tip < 1e-12, f"tip positions differ from the trajectory's by {worst_tip} m")
        points, arrays = last
        nodes = np.asarray(result["nodes"]["position"])
        final = np.abs(points - nodes).max()
        check(points.shape == nodes.shape and final < 1e-12,
              f"last frame's points differ from the result's nodes by {final} m")
        d1, d2, d3 = arrays["d1"], arrays["d2"], arrays["d3"]
        ortho = max(np.abs(np.einsum("ij,ij->i", a, b) - (1.0 if a is b else 0.0)).max()
                    for a, b in ((d1, d1), (d2, d2), (d3, d3), (d1, d2), (d2, d3), (d1, d3)))
        check(ortho < 1e-2, f"directors not orthonormal: {ortho}")
        # The result writes the rotation nearest the tip frame (M = U P → U): they differ by
        # U (P − I), P − I ≈ (MᵀM − I)/2, whose entries are within √3/2 of ortho.
        tip_R = np.asarray(result["tip"]["rotation"])
        tip_directors = np.column_stack([d1[-1], d2[-1], d3[-1]])
        check(np.abs(tip_directors - tip_R).max() < ortho + 1e-12,
              f"tip directors {tip_directors} against the result's tip rotation {tip_R}")
        rod = spec["rod"]
        r = rod["section"]["radius"]
        clamp_force = arrays["force"][0]
        reaction = np.asarray(result["base_wrench"]["force"])
        check(np.abs(clamp_force + reaction).max() < 1e-12,
              f"clamp force {clamp_force} against the result's reaction {reaction} N")
        check(np.allclose(arrays["radius"], r), "radius point data")
        if "contact_force" in result["nodes"]:
            contact = np.abs(arrays["contact_force"] - np.asarray(result["nodes"]["contact_force"]))
            check(contact.max() < 1e-12 * max(1.0, np.abs(arrays["contact_force"]).max()),
                  f"contact force differs from the result's by {contact.max()} N/m")
        # A shorter run into the same directory replaces the series: ParaView groups every
        # run_NNNNNN.vtp there, so none of the longer run's frames may be left behind.
        short = dict(spec, dynamics=dict(spec["dynamics"], duration=spec["dynamics"]["duration"] / 2))
        short_path = os.path.join(work, "short.json")
        with open(short_path, "w") as f:
            json.dump(short, f)
        _, _, pvd = run(binary, short_path, formulation, work)
        listed = len(ET.parse(pvd).getroot().find("Collection").findall("DataSet"))
        frames = len([f for f in os.listdir(os.path.dirname(pvd)) if f.endswith(".vtp")])
        check(frames == listed and listed < len(datasets),
              f"after a shorter run the directory holds {frames} frames, its .pvd lists {listed}")
        print(f"{len(datasets)} frames; tip {worst_tip:.1e} m, final nodes {final:.1e} m, "
              f"directors orthonormal to {ortho:.1e}, clamp force "
              f"{clamp_force} N")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
