"""Tests of the `cosserat` Python module against analytic results (run by ctest as python.module,
with PYTHONPATH at build/python and the repository root as working directory)."""
import copy
import json
import math
import os
import pathlib
import pickle
import subprocess
import unittest
import warnings

import numpy as np

import cosserat

# A steel wire (r/L = 1/500) clamped at the origin along +z: slender enough that Euler-Bernoulli
# and the elastica hold to (r/L)^2 = 4e-6.
E, G, RHO, R, L = 200e9, 80e9, 8000.0, 1e-3, 0.5
EI = E * math.pi * R**4 / 4
RHO_A = RHO * math.pi * R**2

# beta_n L of the cantilever, from the reference file the C++ tests check their bisection against
# (tests/reference/natural_frequencies.json; Rao 2007).
with open("tests/reference/natural_frequencies.json") as f:
    BETA_L = json.load(f)["beta_L_clamped_free"]


def wire_spec(analysis="statics", extra=None):
    """The wire as a dict with the problem-file keys."""
    problem = {
        "format": "cosserat-problem/1",
        "analysis": analysis,
        "rod": {"length": L, "nodes": 41,
                "section": {"shape": "circle", "radius": R},
                "material": {"youngs_modulus": E, "shear_modulus": G, "density": RHO}},
        "boundary": "cantilever",
        "loads": {},
    }
    problem.update(extra or {})
    return problem


def wire(analysis="statics", extra=None):
    return cosserat.parse_problem(json.dumps(wire_spec(analysis, extra)))


class Environment(unittest.TestCase):
    def test_a_current_bends_a_cantilever_as_beam_theory(self):
        # q L^4 / (8 EI) with q = 1/2 rho_f C_dn D U^2; at delta/L ~ 1e-3 the nonlinearity is
        # O(1e-3) of delta, inside the 1 % (test_fluid_loads.cpp argues it in full).
        loads = cosserat.Loads()
        fluid = cosserat.Fluid()
        fluid.density, fluid.drag_normal, fluid.velocity = 1000.0, 1.2, [0.05, 0, 0]
        loads.fluid = fluid
        solver = cosserat.StaticSolver(wire())
        self.assertTrue(solver.solve(loads).converged)
        q = 0.5 * 1000.0 * 1.2 * 2 * R * 0.05**2
        expected = q * L**4 / (8 * EI)
        self.assertLess(expected, 2e-3 * L)
        self.assertAlmostEqual(solver.state()["position"][-1][0], expected, delta=0.01 * expected)

    def test_contact_forces_come_back_as_numpy_arrays(self):
        # The rod on a table: the table and the clamp together carry the rod's weight (the
        # contact force is integrated by the trapezoid rule on 250 segments, which is exact to
        # O(h^2) of the contact region's curvature: 1e-3 of the weight is ample).
        out = cosserat.solve(cosserat.load_problem(pathlib.Path("examples/rod_on_table.json")))
        self.assertTrue(out["converged"], out["log"])
        forces = out["contact_force"]
        self.assertEqual(forces.shape, (251, 3))
        weight = 8000 * math.pi * 0.002**2 * 9.81 * 2.5
        clamp = out["result"]["base_wrench"]["force"][2]
        self.assertAlmostEqual(out["contact_total_force"][2] + clamp, weight, delta=1e-3 * weight)

    def test_the_environment_of_a_problem_file_is_read(self):
        p = cosserat.load_problem("examples/cantilever_in_current.json")
        self.assertAlmostEqual(p.loads.fluid.density, 1025.0)
        np.testing.assert_allclose(p.loads.fluid.velocity, [0.8, 0, 0])
        self.assertAlmostEqual(p.loads.fluid.added_mass, 1.0)


class ProblemFiles(unittest.TestCase):
    def test_reads_the_default_problem(self):
        p = cosserat.load_problem("examples/cantilever.json")
        self.assertEqual(p.analysis, "statics")
        self.assertEqual(p.nodes, 41)
        self.assertAlmostEqual(p.length, 0.5)
        np.testing.assert_allclose(p.loads.tip_force, [-0.2, 0, 0])

    def test_the_logs_warnings_are_python_warnings(self):
        # A round steel column pressed to 2.5 times its Euler load stands straight, unstable
        # (the planar bow's pins would have passed each other by 0.0960 L): the log's warning
        # is also a RuntimeWarning, as a notebook shows it; a run with nothing to warn of
        # raises none.
        EI = 200e9 * math.pi * 1e-12 / 4
        column = {"format": "cosserat-problem/1", "boundary": "pinned-pinned",
                  "rod": {"length": 1, "nodes": 41,
                          "section": {"shape": "circle", "radius": 0.001},
                          "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9,
                                       "density": 8000}},
                  "loads": {"tip_force": [0, 0, -2.5 * math.pi ** 2 * EI]}}
        with self.assertWarnsRegex(RuntimeWarning,
                                   r"^the column is compressed .* passed each other \(0\.096 L\)"):
            out = cosserat.solve(column)
        self.assertIn("cosserat: warning: the column is compressed", out["log"])
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            cosserat.solve("examples/cantilever.json")

    def test_bad_input_names_the_field(self):
        text = json.dumps({"format": "cosserat-problem/1", "analysis": "statics",
                           "rod": {"length": -1, "section": {"shape": "circle", "radius": R},
                                   "material": {"youngs_modulus": E, "density": RHO}}})
        with self.assertRaisesRegex(ValueError, "rod.length"):
            cosserat.parse_problem(text)
        with self.assertRaisesRegex(ValueError, "no_such_file.json"):
            cosserat.load_problem("no_such_file.json")
        # A byte that is not UTF-8 is quoted as \xNN: the message is not lost (it was empty).
        with self.assertRaisesRegex(ValueError, r"invalid JSON at line 1, .*\\xFF"):
            cosserat.parse_problem(b'{"format": "cosserat\xff"}')
        # JSON text where a path is expected: said so, not echoed back as a missing file name.
        with self.assertRaisesRegex(ValueError, "got JSON text, expected a file path"):
            cosserat.solve(text)

    def test_assembly_statics_give_each_rod_as_arrays(self):
        # The guided beam: per rod, its name, s and positions as NumPy arrays, the result's own
        # numbers, starting at the file's bases (x = -0.05 and 0.05 m).
        out = cosserat.solve("examples/guided_beam.json")
        self.assertEqual([r["name"] for r in out["rods"]], ["left", "right"])
        for rod, doc, x in zip(out["rods"], out["result"]["assembly"]["rods"], (-0.05, 0.05)):
            self.assertEqual(rod["position"].shape, (len(doc["nodes"]["s"]), 3))
            np.testing.assert_array_equal(rod["position"], np.asarray(doc["nodes"]["position"]))
            np.testing.assert_array_equal(rod["position"][0], [x, 0, 0])
        # The problem names its rods; a single rod's length, nodes, ends and base are None, not
        # a single rod's defaults (0.0 m, 41 nodes, "cantilever") that no file gave.
        problem = cosserat.load_problem("examples/guided_beam.json")
        self.assertEqual(problem.rods, ["left", "right"])
        for key in ("length", "nodes", "boundary", "base_position", "base_rotation"):
            self.assertIsNone(getattr(problem, key), key)
        single = cosserat.load_problem("examples/cantilever.json")
        self.assertIsNone(single.rods)
        self.assertEqual(single.length, 0.5)

    def test_the_static_solver_checks_its_grid_as_the_command_does(self):
        # A shot that ran away (a gel rod's chamber at 1e9 Pa: "converged", tip at 1e255 m) is
        # non_finite, and a coarse grid for the bend warns, as from cosserat.solve.
        runaway = cosserat.StaticSolver("tests/cli/chamber_pressure_runaway.json")
        with self.assertWarnsRegex(RuntimeWarning, "its shot ran away"):
            self.assertEqual(runaway.solve().status, "non_finite")
        coarse = cosserat.StaticSolver("tests/cli/arc_on_a_coarse_grid.json")
        with self.assertWarnsRegex(RuntimeWarning, "grid resolves the shape coarsely"):
            self.assertTrue(coarse.solve().converged)

    def test_a_missing_file_is_a_file_not_found_error_and_a_value_error(self):
        for call in (cosserat.load_problem, cosserat.solve, cosserat.StaticSolver):
            with self.assertRaises(FileNotFoundError) as caught:
                call("no/such/problem.json")
            self.assertIsInstance(caught.exception, ValueError)  # as any unreadable problem
            self.assertEqual(caught.exception.filename, "no/such/problem.json")

    def test_bools_are_refused_where_numbers_are_read(self):
        # A file's `true` is no number; neither is Python's True in a step's loads, a dt or an
        # actuation (it had become 1.0 N, or a 1 s step).
        with self.assertRaisesRegex(ValueError, r"loads\.tip_force\[0\]: expected a number"):
            cosserat.Stepper(wire("dynamics")).step({"tip_force": [True, 0, 0]})
        with self.assertRaisesRegex(ValueError, r"^dt: expected a number"):
            cosserat.Stepper(wire("dynamics"), dt=True)
        stepper = cosserat.Stepper(wire("dynamics"))
        stepper.initialize_at_rest()
        with self.assertRaisesRegex(ValueError, r"^base_position\[1\]: expected a number"):
            stepper.step(base_position=[0, True, 0])
        with self.assertRaisesRegex(ValueError, r"^base_position\[0\]: expected a number"):
            cosserat.StaticSolver(wire()).solve(base_position=[True, 0, 0])
        with self.assertRaisesRegex(ValueError, r"actuation\.tendon_tension\[1\]"):
            cosserat.Actuation(tendon_tension=[1.0, False])
        loads = cosserat.Loads(gravity=[0, 0, -9.81], tip_force=[0, 0.1, 0])  # keywords
        self.assertEqual(list(loads.tip_force), [0, 0.1, 0])
        with self.assertRaisesRegex(ValueError, r"tip_force\[0\]: expected a number"):
            loads.tip_force = np.array([True, False, False])
        with self.assertRaisesRegex(TypeError, r"unknown field 'tipforce'"):
            cosserat.Loads(tipforce=[1, 0, 0])

    def test_non_finite_loads_are_refused(self):
        loads = cosserat.Loads()
        loads.tip_force = [math.nan, 0, 0]
        with self.assertRaisesRegex(ValueError, "loads"):
            cosserat.StaticSolver(wire()).solve(loads)
        with self.assertRaisesRegex(ValueError, "tip_force_frame"):
            loads.tip_force_frame = "sideways"
        with self.assertRaisesRegex(ValueError, "base_rotation"):
            cosserat.StaticSolver(wire()).solve(cosserat.Loads(), base_rotation=2 * np.eye(3))
        stepper = cosserat.Stepper(wire("dynamics"))
        stepper.initialize_at_rest()
        with self.assertRaisesRegex(ValueError, "base_position"):
            stepper.step(base_position=[0, math.inf, 0])
        # A base so far out that a double loses the rod's shape there (the file's rule: within
        # 1e9 rod lengths of the origin), and loads of the wrong type, are refused by name.
        for far in ([1e17, 0, 0], [0, 0, -1e300]):
            with self.assertRaisesRegex(ValueError, "base_position: expected a point within 1e9"):
                stepper.step(base_position=far)
            with self.assertRaisesRegex(ValueError, "base_position: expected a point within 1e9"):
                cosserat.StaticSolver(wire()).solve(base_position=far)
        with self.assertRaisesRegex(TypeError, "loads: expected a cosserat.Loads or a dict"):
            cosserat.StaticSolver(wire()).solve(loads=5)
        with self.assertRaisesRegex(TypeError, "loads: expected a cosserat.Loads or a dict"):
            stepper.step(loads=5)

    def test_other_formulations_and_ends_are_refused(self):
        with self.assertRaisesRegex(ValueError, "formulation"):
            cosserat.Stepper(wire("dynamics", {"formulation": "quaternion-fd"}))
        with self.assertRaisesRegex(ValueError, "formulation"):
            cosserat.StaticSolver(wire("statics", {"formulation": "quaternion-fd"}))
        with self.assertRaisesRegex(ValueError, "boundary"):
            cosserat.Stepper(wire("dynamics", {"boundary": "pinned-pinned"}))

    def test_a_problems_actuation_edited_in_place_is_solved(self):
        # p.actuation is the problem's own, as p.loads is: a tension edited in place is the one
        # solved, the same result as the same actuation assigned whole (a copy had made the
        # edit a silent no-op). An edit the rules refuse is named by solve().
        edited = cosserat.load_problem("robots/tendon_three_tendon.json")
        edited.actuation.tendon_tension[:3] = [0.2, 0.0, 0.0]
        assigned = cosserat.load_problem("robots/tendon_three_tendon.json")
        assigned.actuation = cosserat.Actuation(tendon_tension=[0.2, 0.0, 0.0])
        a, b = cosserat.solve(edited)["result"], cosserat.solve(assigned)["result"]
        self.assertEqual(a["robot"]["tendon_tension"], [0.2, 0.0, 0.0])
        self.assertEqual(a["tip"], b["tip"])
        self.assertNotEqual(a["tip"], cosserat.solve(cosserat.load_problem(
            "robots/tendon_three_tendon.json"))["result"]["tip"])  # the file's tensions differ
        edited.actuation.tendon_tension[1] = float("nan")
        with self.assertRaisesRegex(ValueError, "actuation.tendon_tension"):
            cosserat.solve(edited)
        # Assigned, an Actuation that sets only tensions keeps the jamming robot's jams (as a
        # solver fits one); a solver made before an edit keeps the problem it was made with.
        jam = cosserat.load_problem("robots/jamming_virtual_joints.json")
        kept = np.array(jam.actuation.jamming_pressure)
        solver = cosserat.StaticSolver(jam)
        self.assertTrue(solver.solve().converged)
        before = solver.state()["position"][-1]
        jam.actuation = cosserat.Actuation(tendon_tension=[1.0])
        np.testing.assert_array_equal(jam.actuation.jamming_pressure, kept)
        self.assertTrue(solver.solve().converged)
        np.testing.assert_array_equal(solver.state()["position"][-1], before)


class Statics(unittest.TestCase):
    def test_a_column_pressed_past_its_buckling_load_is_warned_unstable(self):
        # The wire as a column under twice Euler's load pi^2 EI / (4 L^2): the warm solver stays
        # on the straight branch, unstable in both lateral planes, and says so; below, stable.
        critical = math.pi**2 * EI / (4 * L**2)
        solver = cosserat.StaticSolver(wire())
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # below the load: no warning at all
            below = solver.solve({"tip_force": [0, 0, -0.5 * critical]})
        self.assertEqual(below.stability_index, 0)
        with self.assertWarnsRegex(RuntimeWarning, r"unstable \(2 unstable direction"):
            above = solver.solve({"tip_force": [0, 0, -2 * critical]})
        self.assertEqual(above.stability_index, 2)  # both lateral planes of the round wire
        self.assertIn("stability_index=2", repr(above))
        # On a frictionless surface nothing settles: a finger pressed on a sphere slips off
        # sideways (one unstable direction), and the warning says so, as the command's does.
        with open("examples/finger_on_sphere.json") as f:
            finger = json.load(f)
        finger["formulation"] = "se3-shooting"
        with self.assertWarnsRegex(RuntimeWarning, "the rod can slide off them"):
            self.assertEqual(cosserat.StaticSolver(finger).solve().stability_index, 1)

    def test_tip_load_matches_the_elastica(self):
        # Bisshopp & Drucker's closed form (tests/reference/elastica_tip_load.json). Tolerance
        # 2e-5 L: shear and extension of the wire move the tip by O((r/L)^2) = 4e-6 L (measured
        # up to 4.0e-6 L at alpha = 2), RK4 at 40 segments by far less.
        with open("tests/reference/elastica_tip_load.json") as f:
            rows = json.load(f)["rows"]
        solver = cosserat.StaticSolver(wire())
        for row in rows[:4]:
            loads = cosserat.Loads()
            loads.tip_force = [-row["alpha"] * EI / L**2, 0, 0]
            summary = solver.solve(loads)
            self.assertTrue(summary.converged, summary.status)
            state = solver.state()
            tip = state["position"][-1]
            self.assertAlmostEqual(-tip[0] / L, row["deflection_over_L"], delta=2e-5)
            self.assertAlmostEqual(tip[2] / L, row["axial_over_L"], delta=2e-5)
            # The section frames (N x 3 x 3): the tip's tangent, its third column, turns by the
            # elastica's tip angle (same O((r/L)^2) argument; measured up to 6.4e-5 degrees).
            rotation = state["rotation"]
            self.assertEqual(rotation.shape, (41, 3, 3))
            tangent = rotation[-1][:, 2]
            angle = math.degrees(math.atan2(-tangent[0], tangent[2]))
            self.assertAlmostEqual(angle, row["tip_angle_deg"], delta=1e-3)

    def test_straight_tendon_bends_to_constant_curvature(self):
        # One tendon parallel to the backbone at offset d, no external load: the backbone carries
        # the moment tau d everywhere (Rucker & Webster), so its curvature is tau d / EI along
        # the whole length. Residual tolerance 1e-10 of EI/L: 1e-9 relative holds (measured
        # 2e-16).
        p = cosserat.load_problem("robots/tendon_three_tendon.json")
        np.testing.assert_allclose(p.actuation.tendon_tension[:3], [1.5, 0.0, 0.5])
        solver = cosserat.StaticSolver(p)
        actuation = cosserat.Actuation()
        actuation.tendon_tension = [2.0, 0.0, 0.0]
        self.assertTrue(solver.solve(cosserat.Loads(), actuation=actuation).converged)
        ei = 210e9 * math.pi * 0.0004**4 / 4
        curvature = np.linalg.norm(solver.state()["strain_B"][:, :3], axis=1)
        np.testing.assert_allclose(curvature, 2.0 * 0.008 / ei, rtol=1e-9)
        # Written in place, as the C++ idiom reads (the array is a view of the Actuation).
        actuation.tendon_tension[0] = 1.0
        self.assertTrue(solver.solve(cosserat.Loads(), actuation=actuation).converged)
        curvature = np.linalg.norm(solver.state()["strain_B"][:, :3], axis=1)
        np.testing.assert_allclose(curvature, 1.0 * 0.008 / ei, rtol=1e-9)
        with self.assertRaisesRegex(ValueError, "tendon_tension"):
            actuation.tendon_tension = [1.0] * 9
        actuation.tendon_tension = [-1.0, 0.0, 0.0]
        with self.assertRaisesRegex(ValueError, "tendon_tension"):
            solver.solve(cosserat.Loads(), actuation=actuation)
        # Past the tendon law's limit, τ d²/EI = 1 at 66 N, the inside of the bend would shrink
        # to nothing and the shot fails: non_finite, with the command's hint as a warning that
        # names the ratio, 100 × 0.008² / EI = 1.52.
        actuation.tendon_tension = [100.0, 0.0, 0.0]
        with self.assertWarnsRegex(RuntimeWarning, r"tendon strain law.* = 1\.52 "):
            summary = solver.solve(cosserat.Loads(), actuation=actuation)
        self.assertEqual(summary.status, "non_finite")
        # Tendon lengths are an inverse solve, which cosserat.solve runs; this solver says so.
        with self.assertRaisesRegex(ValueError, r"actuation\.length: .*cosserat\.solve\(\)"):
            solver.solve(actuation={"length": [0.25, 0.25, 0.25]})


    def test_chamber_pressure_bends_its_segment_only(self):
        # The arm's lower chamber at +x (6 mm, A = 2.827e-5 m^2) at pressure p, no load: the
        # lower segment takes the curvature -p A d / EI about body y, the upper one none
        # (constitutive/chamber_law.hpp). Exact in the law, to the solver tolerance.
        p = cosserat.load_problem("robots/pneumatic_two_segment_arm.json")
        np.testing.assert_allclose(p.actuation.chamber_pressure[:6], [1.2e5, 0, 0, 0, 8e4, 4e4])
        solver = cosserat.StaticSolver(p)
        actuation = cosserat.Actuation()
        actuation.chamber_pressure = [1e5, 0, 0, 0, 0, 0]
        self.assertTrue(solver.solve(cosserat.Loads(), actuation=actuation).converged)
        ei = 1.5e6 * math.pi * 0.012**4 / 4
        state = solver.state()
        lower = state["s"] < 0.15
        np.testing.assert_allclose(state["strain_B"][lower, 1], -1e5 * 2.827e-5 * 0.006 / ei,
                                   rtol=1e-9)
        np.testing.assert_allclose(state["strain_B"][~lower, :3], 0, atol=1e-12)
        actuation.chamber_pressure = [0] * 6 + [1e5]  # a seventh chamber the arm does not have
        with self.assertRaisesRegex(ValueError, "chamber_pressure"):
            solver.solve(cosserat.Loads(), actuation=actuation)

class Dynamics(unittest.TestCase):
    def test_first_bending_frequency_is_euler_bernoulli(self):
        # A small tip load released, no gravity, no damping: the tip swings at the first
        # cantilever frequency (beta1 L = 1.8751). BDF2 at dt = 1 ms shifts it by O((w dt)^2)
        # ~ 1e-3 (w dt = 0.035), the wire's shear by ~(r/L)^2; measured -0.25 % over the three
        # periods in 0.6 s. The acceptance: 1 %.
        p = wire("dynamics", {"dynamics": {"dt": 1e-3, "duration": 1.0,
                                           "initial_loads": {"tip_force": [-1e-3, 0, 0]}}})
        stepper = cosserat.Stepper(p)
        self.assertTrue(stepper.initialize_at_rest().converged)
        x, t = [], []
        for _ in range(600):
            summary = stepper.step(cosserat.Loads())
            self.assertTrue(summary.converged, summary.status)
            x.append(stepper.tip_position()[0])
            t.append(stepper.time)
        x, t = np.array(x), np.array(t)
        # Upward zero crossings, linearly interpolated; the period is their mean spacing.
        i = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
        crossings = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
        measured = 1.0 / np.mean(np.diff(crossings))
        expected = BETA_L[0]**2 / (2 * math.pi * L**2) * math.sqrt(EI / RHO_A)
        self.assertGreaterEqual(len(crossings), 3)
        self.assertAlmostEqual(measured / expected, 1.0, delta=0.01)

    def test_the_default_scheme_pairs_segments_where_the_step_allows(self):
        # The wire at dt = 2 ms: lambda L = L (c0^2 rho A / EI)^(1/4) = 8.7 with c0 = 1.5/dt, so
        # a pair of its 40 segments has 2 h lambda = 0.43 <= 1/2 and all 40 pair; Heun and RK4
        # step every segment.
        p = wire("dynamics", {"dynamics": {"dt": 2e-3}})
        self.assertEqual(cosserat.Stepper(p).shot_steps, 20)
        self.assertEqual(cosserat.Stepper(p, spatial_scheme="heun").shot_steps, 40)
        self.assertEqual(cosserat.Stepper(p, spatial_scheme="rk4").shot_steps, 40)
        with self.assertRaisesRegex(ValueError, "spatial_scheme"):
            cosserat.Stepper(p, spatial_scheme="euler")

    def test_rest_stays_rest_and_restore_repeats_a_run(self):
        loads = cosserat.Loads()
        loads.gravity = [-9.81, 0, 0]
        p = wire("dynamics", {"dynamics": {"dt": 2e-3, "spatial_scheme": "heun"}})
        stepper = cosserat.Stepper(p)
        self.assertTrue(stepper.initialize_at_rest(loads).converged)
        rest = stepper.tip_position()
        for _ in range(50):
            self.assertTrue(stepper.step(loads).converged)
        # A rod at rest in its equilibrium stays there (drift below 1e-10 L).
        self.assertLess(np.linalg.norm(stepper.tip_position() - rest), 1e-10 * L)
        # Released from a save point, the same steps give the same state, bit for bit.
        saved = stepper.save()
        kick = cosserat.Loads()
        kick.gravity = loads.gravity
        kick.tip_force = [0, 0.05, 0]
        runs = []
        for _ in range(2):
            stepper.restore(saved)
            for _ in range(20):
                self.assertTrue(stepper.step(kick).converged)
            runs.append(stepper.state()["position"].copy())
        np.testing.assert_array_equal(runs[0], runs[1])
        self.assertGreater(np.linalg.norm(runs[0][-1] - rest), 1e-6)

    def test_steppers_warn_as_the_command_does_before_a_run(self):
        # An undamped silicone rod on 21 nodes at dt = 1 ms: the shear wave's exponent per segment
        # is 1.36, above the 1 where converged steps gained energy sixfold a step; the command
        # logs a warning before its result, and the Python steppers raise the same one. At
        # dt = 2 ms (0.68) neither warns.
        soft = {"format": "cosserat-problem/1", "analysis": "dynamics",
                "rod": {"length": 0.3, "nodes": 21,
                        "section": {"shape": "circle", "radius": 0.005},
                        "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.5,
                                     "density": 1100}},
                "loads": {"gravity": [0, 0, -9.81]}}
        with self.assertWarnsRegex(RuntimeWarning, r"exponent per segment is 2\.12 .*shear 1\.36"):
            cosserat.Stepper(soft, dt=0.001)
        with self.assertWarnsRegex(RuntimeWarning, r"shear 1\.36"):
            cosserat.BatchStepper(dict(soft, dynamics={"dt": 0.001}), 2, threads=1)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            cosserat.Stepper(soft, dt=0.002)
        # At dt = 1e-9 s the shear wave alone asks for (1.5/dt) L sqrt(ρA/κGA)/0.9 ≈ 1e7 nodes,
        # past the file's limit of 10⁶: the advice is a larger dt, not a node count refused.
        with self.assertWarnsRegex(RuntimeWarning, r"a larger dt: this one needs [0-9.e+]+ nodes, "
                                   r"past the limit of 1000000"):
            cosserat.Stepper(soft, dt=1e-9)

    def test_actuation_and_loads_edited_in_place_are_applied(self):
        # A stepper's actuation and loads edited in place are what its next step applies: the
        # same run, bit for bit, as the same values given to step(). An edit the file's rules
        # refuse (a negative tension) is named at that step, and the step is not taken.
        p = cosserat.load_problem("tests/cli/tendon_dynamics.json")
        a, b = cosserat.Stepper(p), cosserat.Stepper(p)
        self.assertTrue(a.initialize_at_rest().converged and b.initialize_at_rest().converged)
        a.actuation.tendon_tension[:3] = [1.0, 0.5, 0.0]
        a.loads.tip_force[0] = 0.1  # a writable view of the stepper's loads
        for _ in range(20):
            self.assertTrue(a.step().converged)
            self.assertTrue(b.step({"gravity": list(p.loads.gravity), "tip_force": [0.1, 0, 0]},
                                   actuation={"tension": [1.0, 0.5, 0.0]}).converged)
        np.testing.assert_array_equal(a.tip_position(), b.tip_position())
        # Assigned, an actuation is fitted as step() fits one: a dict's tensions, the rest the
        # problem's; the next step applies it as the same dict given to step().
        a.actuation = {"tension": [0.2, 0.1, 0.0]}
        self.assertTrue(a.step().converged)
        self.assertTrue(b.step({"gravity": list(p.loads.gravity), "tip_force": [0.1, 0, 0]},
                               actuation={"tension": [0.2, 0.1, 0.0]}).converged)
        np.testing.assert_array_equal(a.tip_position(), b.tip_position())
        # Loads assigned as a dict are read as step() reads one.
        a.loads = {"gravity": list(p.loads.gravity), "tip_force": [0.3, 0, 0]}
        self.assertTrue(a.step().converged)
        self.assertTrue(b.step({"gravity": list(p.loads.gravity), "tip_force": [0.3, 0, 0]},
                               actuation={"tension": [0.2, 0.1, 0.0]}).converged)
        np.testing.assert_array_equal(a.tip_position(), b.tip_position())
        with self.assertRaisesRegex(ValueError, "^loads.tip_froce: unknown key"):
            a.loads = {"tip_froce": [1, 0, 0]}
        with self.assertRaisesRegex(TypeError, "^loads: expected a cosserat.Loads or a dict"):
            a.loads = [1, 0, 0]
        a.actuation.tendon_tension[0] = -1.0
        t = a.time
        with self.assertRaisesRegex(ValueError, "actuation.tendon_tension"):
            a.step()
        self.assertEqual(a.time, t)
        # A vector given the wrong type is named, as a dict's would be.
        with self.assertRaisesRegex(TypeError, "^tip_force: expected a list of numbers"):
            a.loads.tip_force = "abc"
        with self.assertRaisesRegex(ValueError, "^tip_force: expected 3 numbers, got 2"):
            a.loads.tip_force = [1, 2]
        with self.assertRaisesRegex(TypeError, "^tendon_tension: expected a list of numbers"):
            cosserat.Actuation(tendon_tension="abc")

    def test_a_step_takes_loads_and_actuation_as_dicts(self):
        # The same inputs as objects or as dicts with the problem file's keys: the same run, bit
        # for bit. A misspelt key is named.
        p = cosserat.load_problem("tests/cli/tendon_dynamics.json")
        a, b = cosserat.Stepper(p), cosserat.Stepper(p)
        self.assertTrue(a.initialize_at_rest().converged and b.initialize_at_rest().converged)
        loads = cosserat.Loads()
        loads.gravity, loads.tip_force = [0, 0, -9.81], [0.1, 0, 0]
        act = cosserat.Actuation()
        act.tendon_tension = [1.0, 0.5, 0.0]
        for _ in range(20):
            self.assertTrue(a.step(loads, actuation=act).converged)
            self.assertTrue(b.step({"gravity": [0, 0, -9.81], "tip_force": [0.1, 0, 0]},
                                   actuation={"tension": [1.0, 0.5, 0.0]}).converged)
        np.testing.assert_array_equal(a.tip_position(), b.tip_position())
        with self.assertRaisesRegex(ValueError, r"loads\.gravty: unknown key"):
            b.step({"gravty": [0, 0, -9.81]})
        # A value of the wrong shape is named by its key, as in a file.
        with self.assertRaisesRegex(ValueError, r"loads\.tip_force: expected an array of 3"):
            b.step({"gravity": [0, 0, -9.81], "tip_force": [0, 0.01]})
        with self.assertRaisesRegex(ValueError, r"loads\.gravity: expected an array of 3"):
            b.step({"gravity": -9.81})
        # A base wrench acts on a free-free rod's end only: on a clamped one it is refused.
        with self.assertRaisesRegex(ValueError, r"base_wrench_B: acts on a free-free rod"):
            b.step(base_wrench_B=[0, 0, 0, 100.0, 0, 0])
        # Left out, gravity is not there, as in a file; it is the load a controller most likely
        # meant to keep, so the step says so.
        with self.assertWarnsRegex(RuntimeWarning, 'the dict has no "gravity"'):
            b.step({"tip_force": [0.1, 0, 0]})
        with self.assertWarnsRegex(RuntimeWarning, "this Loads has no gravity"):
            b.step(cosserat.Loads())
        with self.assertRaisesRegex(ValueError, r"actuation\.tensions: unknown key"):
            b.step(actuation={"tensions": [1.0]})
        # As in a file, one tension per tendon: a short list is refused, not zero-filled.
        with self.assertRaisesRegex(ValueError, r"actuation\.tension: expected one value per "
                                                r"tendon \(3 in robot\.tendons\)"):
            b.step(actuation={"tension": [1.0]})
        # Tendon lengths are statics' inverse solve: the message says where it runs.
        with self.assertRaisesRegex(ValueError, r"actuation\.length: .*cosserat\.solve\(\)"):
            b.initialize_at_rest(actuation={"length": [0.1, 0.1, 0.1]})
        # The static solver takes the same dicts: the same equilibrium as with objects.
        objects, dicts = cosserat.StaticSolver(p), cosserat.StaticSolver(p)
        self.assertTrue(objects.solve(loads, actuation=act).converged)
        self.assertTrue(dicts.solve({"gravity": [0, 0, -9.81], "tip_force": [0.1, 0, 0]},
                                    actuation={"tension": [1.0, 0.5, 0.0]}).converged)
        np.testing.assert_array_equal(objects.state()["position"], dicts.state()["position"])
        with self.assertRaisesRegex(ValueError, r"actuation\.tension: expected one value"):
            dicts.solve(actuation={"tension": [1.0]})
        # Left out, the pressures the section reads stay the problem's (the jamming robot kept
        # jammed, not silently released to a tip 0.4 m off); a pressure no section reads is
        # refused, as in a file.
        jammed = cosserat.StaticSolver("robots/jamming_virtual_joints.json")
        self.assertTrue(jammed.solve().converged)
        tip = jammed.state()["position"][-1]
        self.assertTrue(jammed.solve(actuation={"tension": [1.0]}).converged)
        np.testing.assert_array_equal(jammed.state()["position"][-1], tip)
        with self.assertRaisesRegex(ValueError, r"actuation\.pressure: expected a "
                                                r"rod\.stiffness_profile that depends on it"):
            cosserat.StaticSolver("robots/pneumatic_finger.json").solve(
                actuation={"pressure": 1.5e5})

    def test_stepper_runs_a_problem_as_the_command_does(self):
        # A tendon robot released from zero tension (its initial actuation) to the robot's
        # tensions: the Stepper, left to its defaults, applies the same inputs as `cosserat
        # solve`, so the final tips are the same numbers (the JSON keeps 17 digits).
        p = cosserat.load_problem("tests/cli/tendon_dynamics.json")
        np.testing.assert_array_equal(p.initial_actuation.tendon_tension[:3], [0, 0, 0])
        command = cosserat.solve(p)["result"]["tip"]["position"]
        stepper = cosserat.Stepper(p)
        self.assertTrue(stepper.initialize_at_rest().converged)
        for _ in range(int(round(p.duration / p.dt))):
            self.assertTrue(stepper.step().converged)
        np.testing.assert_array_equal(stepper.tip_position(), command)
        np.testing.assert_array_equal(stepper.actuation.tendon_tension, p.actuation.tendon_tension)

    def test_stepper_runs_a_column_as_the_command_does(self):
        # A clamped-clamped wire at half its Euler load, let go from a side load: the Stepper
        # holds the tip on the clamp's axis as `cosserat solve` does, so the final shape and
        # the clamp's wrench are the same numbers (the JSON keeps 17 digits).
        spec = json.load(open("tests/cli/column_dynamics.json"))
        command = cosserat.solve(spec)["result"]
        stepper = cosserat.Stepper(spec)
        self.assertTrue(stepper.initialize_at_rest().converged)
        for _ in range(int(round(spec["dynamics"]["duration"] / spec["dynamics"]["dt"]))):
            self.assertTrue(stepper.step().converged)
        np.testing.assert_array_equal(stepper.state()["position"], command["nodes"]["position"])
        # The guide holds the tip on the clamp's axis (the tip's x, y to round-off of 0.5 m).
        np.testing.assert_allclose(stepper.tip_position()[:2], [0, 0], atol=1e-12)
        np.testing.assert_array_equal(stepper.base_reaction()[3:], command["base_wrench"]["force"])
        # What the guided tip cannot take is refused by name, as the command refuses it.
        with self.assertRaisesRegex(ValueError, r"^base_position: a column's clamp"):
            stepper.step(base_position=[0, 0, 0.01])
        other = cosserat.Stepper("tests/cli/tendon_dynamics.json")
        self.assertTrue(other.initialize_at_rest().converged)
        with self.assertRaisesRegex(ValueError, r"^snapshot: taken from a rod with other end"):
            stepper.restore(other.save())
        spec["boundary"] = "clamped-pinned"
        pinned = cosserat.Stepper(spec)
        self.assertTrue(pinned.initialize_at_rest().converged)
        with self.assertRaisesRegex(ValueError, r"^loads\.tip_moment: a column's pinned tip"):
            pinned.step({"tip_force": [0, 0, -12.4], "tip_moment": [0, 0.1, 0]})
        with self.assertRaisesRegex(ValueError, r"^loads\.tip_moment: a column's pinned tip"):
            pinned.initialize_at_rest({"tip_force": [0, 0, -12.4], "tip_moment": [0, 0.1, 0]})
        spec["dynamics"]["initial_loads"]["tip_moment"] = [0, 0.1, 0]
        with self.assertRaisesRegex(ValueError, r"^dynamics\.initial_loads\.tip_moment: a "
                                                r"column's pinned tip"):
            cosserat.Stepper(spec)
        del spec["dynamics"]["initial_loads"]["tip_moment"]
        spec["dynamics"]["tip_mass"] = 0.01
        with self.assertRaisesRegex(ValueError, r"^dynamics\.tip_mass: a body at a column's"):
            cosserat.Stepper(spec)

    def test_initialize_at_rest_resets_the_inputs_as_well_as_the_state(self):
        # An episode with other tensions and a moved, moving clamp, then initialize_at_rest():
        # the next episode, given nothing, repeats a fresh Stepper's run bit for bit (it rested
        # and stepped with the last episode's base and tensions before).
        p = cosserat.load_problem("tests/cli/tendon_dynamics.json")
        fresh, used = cosserat.Stepper(p), cosserat.Stepper(p)
        self.assertTrue(used.initialize_at_rest().converged)
        for _ in range(5):
            self.assertTrue(used.step(actuation={"tension": [0, 2, 0]}, base_position=[0, 0, 0.01],
                                      base_twist_B=[0, 0, 0, 0, 0, 0.01]).converged)
        for s in (fresh, used):
            self.assertTrue(s.initialize_at_rest().converged)
            for _ in range(5):
                self.assertTrue(s.step().converged)
        np.testing.assert_array_equal(used.tip_position(), fresh.tip_position())
        # A batch that would not fit in memory is refused before it is allocated (1e9 rods were
        # allocated until the kernel killed the process).
        with self.assertRaisesRegex(ValueError, "count: 1000000000 rods of .* GB, more than half"):
            cosserat.BatchStepper(p, 10**9, threads=1)
        b = cosserat.BatchStepper(p, 2, threads=1)
        self.assertEqual(b.initialize_at_rest(), 2)
        b.step(tension=[[0, 2, 0], [0, 2, 0]])
        self.assertEqual(b.initialize_at_rest(), 2)
        for _ in range(5):
            self.assertEqual(b.step(), 2)
        np.testing.assert_array_equal(b.tip_positions()[0], fresh.tip_position())

    def test_stepper_energy_and_mass_include_the_tip_body(self):
        # The release with a 20 g payload: the Stepper runs what `cosserat solve` runs, so its
        # energy is the result's (which counts the payload) to round-off, and its mass is the
        # rod's ρAL plus the payload.
        with open("examples/cantilever_release.json") as f:
            p = json.load(f)
        p["dynamics"].update(duration=0.1, tip_mass=0.02, tip_inertia=[1e-6, 1e-6, 2e-7])
        result = cosserat.solve(p)["result"]["energy"]
        stepper = cosserat.Stepper(p)
        self.assertTrue(stepper.initialize_at_rest().converged)
        for _ in range(50):
            self.assertTrue(stepper.step().converged)
        e = stepper.energy()
        for key in ("kinetic", "elastic", "potential"):
            self.assertAlmostEqual(e[key], result[key], delta=1e-12 * abs(result["potential"]))
        self.assertAlmostEqual(stepper.mass(), 8000 * np.pi * 1e-6 * 0.5 + 0.02, delta=1e-12)

    def test_solvers_take_a_problem_as_solve_does(self):
        # A file path and a dict give the same Stepper as the parsed Problem: the same steps,
        # bit for bit; anything else is a TypeError naming the argument.
        path = "examples/cantilever_release.json"
        with open(path) as f:
            as_dict = json.load(f)
        tips = []
        for given in (cosserat.load_problem(path), path, as_dict):
            stepper = cosserat.Stepper(given)
            self.assertTrue(stepper.initialize_at_rest().converged)
            for _ in range(5):
                self.assertTrue(stepper.step().converged)
            tips.append(stepper.tip_position())
        np.testing.assert_array_equal(tips[0], tips[1])
        np.testing.assert_array_equal(tips[0], tips[2])
        self.assertTrue(cosserat.StaticSolver("examples/cantilever.json").solve().converged)
        with self.assertRaisesRegex(TypeError, "problem: expected"):
            cosserat.Stepper(3)

    def test_base_twist_reaches_the_rod(self):
        # The cantilever's base twist is imposed: the rod's s = 0 node moves with it.
        stepper = cosserat.Stepper(wire("dynamics"))
        self.assertTrue(stepper.initialize_at_rest().converged)
        twist = np.array([0.0, 0.1, 0.0, 0.01, 0.0, 0.0])
        self.assertTrue(stepper.step(base_twist_B=twist).converged)
        np.testing.assert_array_equal(stepper.state()["twist_B"][0], twist)

    def test_moving_the_clamp_without_its_twist_warns_once(self):
        # The twist is an input, not derived from the pose: a clamp moved with none given drags
        # the rod. Said once; the same pose again, or a twist given, says nothing.
        stepper = cosserat.Stepper(wire("dynamics"))
        self.assertTrue(stepper.initialize_at_rest().converged)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            stepper.step(base_position=[0, 0, 0])  # where it is
            with self.assertRaises(TypeError):  # refused: nothing applied, the warning included
                stepper.step(base_position=[0, 1e-4])
        with self.assertWarnsRegex(RuntimeWarning, "no base_twist_B was given"):
            stepper.step(base_position=[0, 0, 1e-4])
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            stepper.step(base_position=[0, 0, 2e-4])  # once
            other = cosserat.Stepper(wire("dynamics"))
            self.assertTrue(other.initialize_at_rest().converged)
            other.step(base_position=[0, 0, 1e-4], base_twist_B=[0, 0, 0, 0, 0, 0.05])

    def test_out_of_order_and_foreign_snapshots_are_refused(self):
        stepper = cosserat.Stepper(wire("dynamics"))
        with self.assertRaisesRegex(RuntimeError, "initialize_at_rest"):
            stepper.tip_position()
        with self.assertRaisesRegex(RuntimeError, "initialize_at_rest"):
            stepper.save()
        with self.assertRaisesRegex(RuntimeError, "initialize_at_rest"):
            stepper.step()
        with self.assertRaisesRegex(RuntimeError, "solve"):
            cosserat.StaticSolver(wire()).state()
        # A snapshot of a thicker wire on the same grid does not continue this one.
        other = cosserat.Stepper(cosserat.parse_problem(json.dumps({
            "format": "cosserat-problem/1", "analysis": "dynamics",
            "rod": {"length": L, "nodes": 41, "section": {"shape": "circle", "radius": 2 * R},
                    "material": {"youngs_modulus": E, "shear_modulus": G, "density": RHO}}})))
        self.assertTrue(other.initialize_at_rest().converged)
        self.assertTrue(stepper.initialize_at_rest().converged)
        with self.assertRaisesRegex(ValueError, "another rod"):
            stepper.restore(other.save())

    def test_a_snapshot_at_rest_restores_the_release(self):
        # The peer release: a preload held at rest, released at t = 0. A snapshot of the rest
        # state holds the preload as its last input; restored, the run must still release, so
        # 100 steps match those of the Stepper that was never saved, bit for bit.
        p = cosserat.load_problem("examples/cantilever_release.json")
        original = cosserat.Stepper(p)
        self.assertTrue(original.initialize_at_rest().converged)
        restored = cosserat.Stepper(p)
        self.assertTrue(restored.initialize_at_rest().converged)
        restored.restore(restored.save())
        np.testing.assert_array_equal(restored.loads.tip_force, p.loads.tip_force)
        for _ in range(100):
            self.assertTrue(original.step().converged)
            self.assertTrue(restored.step().converged)
        np.testing.assert_array_equal(restored.tip_position(), original.tip_position())

    def test_a_refused_call_changes_nothing(self):
        # A step with good loads and a bad actuation, or a good base position and a bad
        # rotation, is refused whole: the next step applies what it applied before.
        p = cosserat.load_problem("robots/tendon_three_tendon.json")
        stepper = cosserat.Stepper(p)
        self.assertTrue(stepper.initialize_at_rest().converged)
        loads = copy.copy(stepper.loads)  # stepper.loads is what its next step applies
        loads.tip_force = [0.5, 0, 0]
        bad = cosserat.Actuation()
        bad.tendon_tension = [float("nan"), 0.0, 0.0]
        with self.assertRaisesRegex(ValueError, "actuation.tendon_tension"):
            stepper.step(loads, actuation=bad)
        np.testing.assert_array_equal(stepper.loads.tip_force, p.loads.tip_force)
        with self.assertRaisesRegex(ValueError, "base_rotation"):
            stepper.step(base_position=[0.1, 0, 0], base_rotation=2 * np.eye(3))
        self.assertTrue(stepper.step().converged)
        np.testing.assert_array_equal(stepper.state()["position"][0], p.base_position)
        solver = cosserat.StaticSolver(p)
        with self.assertRaisesRegex(ValueError, "actuation.tendon_tension"):
            solver.solve(loads, actuation=bad)
        self.assertTrue(solver.solve().converged)
        fresh = cosserat.StaticSolver(p)
        self.assertTrue(fresh.solve().converged)
        np.testing.assert_array_equal(solver.state()["position"], fresh.state()["position"])

    def test_rotations_follow_the_problem_file_rule(self):
        # A rotation sent as float32 (orthonormal to ~1e-7) is taken as the nearest rotation, as a
        # problem file's within 1e-6; the clamp then turns the rod's base frame by it exactly.
        stepper = cosserat.Stepper(wire("dynamics"))
        self.assertTrue(stepper.initialize_at_rest().converged)
        c, s = math.cos(0.3), math.sin(0.3)
        exact = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
        self.assertTrue(stepper.step(base_rotation=exact.astype(np.float32)).converged)
        base = stepper.state()["rotation"][0]
        self.assertLess(np.abs(base.T @ base - np.eye(3)).max(), 1e-15)
        np.testing.assert_allclose(base, exact, atol=1e-7)  # float32's rounding
        off = exact.copy()
        off[0, 1] += 2e-6
        with self.assertRaisesRegex(ValueError, r"base_rotation: .*within 1e-6.*got max"):
            stepper.step(base_rotation=off)

    def test_inputs_the_command_drives_in_time_are_refused_by_the_steppers(self):
        # The CLI turns a drill string's clamp (base_spin, rotary_table) and gusts the flow by
        # itself; a Stepper applies what step() is given, so it refuses such files by name.
        for path, field in [("examples/drill_string_stick_slip.json", "dynamics.base_spin"),
                            ("examples/drill_string_motor.json", "dynamics.rotary_table")]:
            with self.assertRaisesRegex(ValueError, field):
                cosserat.Stepper(cosserat.load_problem(path))
        with open("examples/cantilever_in_current.json") as f:
            spec = json.load(f)
        spec["analysis"] = "dynamics"
        spec["environment"]["fluid"]["gust"] = {"amplitude": 0.2, "period": 2.0}
        with self.assertRaisesRegex(ValueError, "environment.fluid.gust"):
            cosserat.Stepper(cosserat.parse_problem(json.dumps(spec)))
        with self.assertRaisesRegex(ValueError, "environment.fluid.gust"):
            cosserat.BatchStepper(cosserat.parse_problem(json.dumps(spec)), 2)

    def test_static_solver_shoots_in_pieces_where_the_command_does(self):
        # A rod lying on a stiff table shoots like e^25 in one piece: StaticSolver then uses
        # multiple shooting, as `cosserat solve` does, and reaches the command's equilibrium
        # exactly (the same solver, options and loads); a failed solve has no state.
        with open("examples/rod_on_table.json") as f:
            spec = json.load(f)
        spec["formulation"] = "se3-shooting"
        solver = cosserat.StaticSolver(cosserat.parse_problem(json.dumps(spec)))
        self.assertTrue(solver.solve().converged)
        self.assertGreater(solver.pieces, 1)
        command = cosserat.solve(spec)
        self.assertTrue(command["converged"])
        np.testing.assert_array_equal(solver.state()["position"], command["nodes"]["position"])
        with self.assertRaisesRegex(ValueError, "actuation: this rod is solved by multiple"):
            solver.solve(actuation=cosserat.Actuation())
        solver = cosserat.StaticSolver(wire())
        loads = cosserat.Loads()
        loads.tip_force = [-1e5, 0, 0]  # 1e5 N on a 1 mm wire: no load path reaches it
        self.assertFalse(solver.solve(loads).converged)
        with self.assertRaisesRegex(RuntimeError, "status"):
            solver.state()

    def test_a_problems_bad_loads_and_a_failed_reset_leave_nothing_to_misread(self):
        # Loads set on a Problem from Python reach every solver made from it checked, as loads
        # handed to a call are (they once ran to status non_finite, or to 0 converged rods).
        p = cosserat.load_problem("robots/tendon_three_tendon.json")
        loads = p.loads
        loads.tip_force = [math.inf, 0, 0]
        p.loads = loads
        for make in (cosserat.StaticSolver, cosserat.Stepper,
                     lambda q: cosserat.BatchStepper(q, 2, threads=1)):
            with self.assertRaisesRegex(ValueError, "loads: tip_force"):
                make(p)
        # A reset that fails (1e9 N on a 0.8 mm backbone) leaves no state: the last run's tip
        # and time would read as this one's.
        stepper = cosserat.Stepper("robots/tendon_three_tendon.json")
        self.assertTrue(stepper.initialize_at_rest().converged)
        self.assertTrue(stepper.step().converged)
        self.assertFalse(stepper.initialize_at_rest(
            loads={"gravity": [0, 0, -9.81], "tip_force": [1e9, 0, 0]}).converged)
        with self.assertRaisesRegex(RuntimeError, "the last initialize_at_rest\\(\\) did not"):
            stepper.tip_position()
        with self.assertRaisesRegex(RuntimeError, "did not converge"):
            stepper.time
        with self.assertRaisesRegex(RuntimeError, "did not converge"):
            stepper.step()
        self.assertTrue(stepper.initialize_at_rest().converged)  # and it starts again
        self.assertTrue(stepper.step().converged)

    def test_actuation_follows_the_problem_file_rules(self):
        p = cosserat.load_problem("robots/tendon_three_tendon.json")
        solver = cosserat.StaticSolver(p)
        for field, value in [("pressure", -1.0), ("tendon_tension", [0, 0, 0, 5.0]),
                             ("jamming_pressure", [-1.0])]:
            a = cosserat.Actuation()
            setattr(a, field, value)
            with self.assertRaisesRegex(ValueError, "actuation." + field):
                solver.solve(actuation=a)
        # A dict's bad values are named under actuation. as an object's are, NaN included; a
        # problem nested past Python's recursion is a ValueError, not a RecursionError.
        for bad in ({"tension": [float("nan"), 0, 0]}, {"tension": [-1.0, 0, 0]}):
            with self.assertRaisesRegex(ValueError, r"^actuation\.tension\[0\]: "):
                solver.solve(actuation=bad)
        deep = {}
        level = deep
        for _ in range(100000):
            level["a"] = {}
            level = level["a"]
        with self.assertRaisesRegex(ValueError, "problem: nested too deeply"):
            cosserat.solve(deep)
        # A dict that holds itself is named where it does.
        looped = {"format": "cosserat-problem/1", "rod": {"length": 1.0}}
        looped["rod"]["section"] = looped
        with self.assertRaisesRegex(ValueError, r"^rod\.section: holds itself"):
            cosserat.solve(looped)
        # Jamming pressures on segments the rod does not have, as the file's rule.
        a = cosserat.Actuation()
        a.jamming_pressure = [1e5]
        with self.assertRaisesRegex(ValueError, "actuation.jamming_pressure: .* 0 switchable"):
            solver.solve(actuation=a)
        jamming = cosserat.load_problem("robots/jamming_virtual_joints.json")
        a.jamming_pressure = [0.0] * 3 + [1e5]
        with self.assertRaisesRegex(ValueError, r"one value per segment \(3 in "
                                    r"rod\.stiffness_profile\.segments\), got 4"):
            cosserat.StaticSolver(jamming).solve(actuation=a)
        with self.assertRaisesRegex(ValueError, "robot.kind"):
            cosserat.Stepper(cosserat.load_problem("robots/eversion_banded_vine.json"))
        with self.assertRaisesRegex(ValueError, "robot.kind"):
            cosserat.StaticSolver(cosserat.load_problem("robots/eversion_banded_vine.json"))

    def test_an_actuation_object_is_fitted_to_the_problem_as_a_dict_is(self):
        # The jamming robot's file inflates its tube (30 kPa: E = 1e6 + 20 p = 1.6 MPa) and jams
        # segments 1 and 3 (80 kPa). One tendon at 1 N on an 8 mm offset, as an object that sets
        # only the tension, keeps those pressures as the dict does: curvature T d / EI with
        # EI = 4.32e-3 N·m² in the compliant segment (1.851 1/m) and 4.32e-3 + 8e7 · 2e-9 in a
        # jammed one (0.0487 1/m); the zeroed pressures gave 2.962 1/m everywhere. To 1e-3:
        # the hand values' own rounding.
        p = cosserat.load_problem("robots/jamming_virtual_joints.json")
        self.assertEqual((p.tendon_count, p.chamber_count, p.jamming_segment_count), (1, 0, 3))
        solver = cosserat.StaticSolver(p)
        self.assertTrue(solver.solve(actuation=cosserat.Actuation(tendon_tension=[1.0])).converged)
        by_object = solver.state()["strain_B"][[5, 15], 1]
        np.testing.assert_allclose(by_object, [0.0487, 1.851], rtol=1e-3)
        self.assertTrue(solver.solve(actuation={"tension": [1.0]}).converged)
        np.testing.assert_array_equal(solver.state()["strain_B"][[5, 15], 1], by_object)
        # A pressure set on the object is its own: the tube deflated, the jams released.
        deflated = cosserat.Actuation(tendon_tension=[1.0], pressure=0.0,
                                      jamming_pressure=[0.0, 0.0, 0.0])
        self.assertTrue(solver.solve(actuation=deflated).converged)
        np.testing.assert_allclose(solver.state()["strain_B"][[5, 15], 1], [2.962, 2.962],
                                   rtol=1e-3)
        # The solver fitted a copy: the object still reads what it was given.
        only_tension = cosserat.Actuation(tendon_tension=[1.0])
        self.assertTrue(solver.solve(actuation=only_tension).converged)
        self.assertEqual(only_tension.pressure, 0.0)
        # A jamming pressure edited in place through its array is the object's own: segment 1
        # at 12.3 kPa, less jammed than at 80 kPa (more than twice the curvature), and the
        # tube's inflation still the problem's (the compliant segment's curvature unchanged).
        edited = cosserat.Actuation(tendon_tension=[1.0])
        edited.jamming_pressure[0] = 12345.0
        self.assertTrue(solver.solve(actuation=edited).converged)
        kappa = solver.state()["strain_B"][[5, 15], 1]
        self.assertGreater(kappa[0], 2 * by_object[0])  # less jammed than at 80 kPa
        self.assertAlmostEqual(kappa[1], by_object[1], delta=1e-3 * by_object[1])
        # So it stays through a pickle; an array only read (printed, compared) is not given:
        # the problem's jams stay, to the bit.
        self.assertEqual(pickle.loads(pickle.dumps(edited)).given()["jamming_pressure"], None)
        read = cosserat.Actuation(tendon_tension=[1.0])
        self.assertEqual(float(read.jamming_pressure.sum()), 0.0)
        self.assertNotIn("jamming_pressure", read.given())
        self.assertTrue(solver.solve(actuation=read).converged)
        np.testing.assert_array_equal(solver.state()["strain_B"][[5, 15], 1], by_object)
        # Another count of tensions than tendons is refused, as in a dict or a file; so is a
        # field the Actuation does not have.
        three = cosserat.StaticSolver("robots/tendon_three_tendon.json")
        for tensions in ([1.0], [1.0, 0, 0, 0]):
            with self.assertRaisesRegex(ValueError, r"actuation\.tendon_tension: expected one "
                                        r"value per tendon \(3 in robot\.tendons\), got"):
                three.solve(actuation=cosserat.Actuation(tendon_tension=tensions))
        # A bad value among them is named by its index, as a dict's is.
        with self.assertRaisesRegex(ValueError, r"^actuation\.tendon_tension\[1\]: expected a "
                                    r"finite tension >= 0 \(N\), got -1$"):
            three.solve(actuation=cosserat.Actuation(tendon_tension=[1.0, -1.0, 0]))
        # An array read back (the object's capacity, zeros past the 3 tendons) is the 3 values;
        # a value past them is not.
        doubled = cosserat.Actuation(tendon_tension=[1.0, 0, 0])
        doubled.tendon_tension = doubled.tendon_tension * 2
        self.assertTrue(three.solve(actuation=doubled).converged)
        with self.assertRaisesRegex(ValueError, r"tendon_tension: .* got 8"):
            three.solve(actuation=cosserat.Actuation(tendon_tension=[1.0] + [0] * 6 + [3.0]))
        # An inflation pressure on a rod whose section reads none (a chambered finger: its
        # pressures are chamber_pressure) is refused as the dict's is, not dropped.
        finger = cosserat.StaticSolver("robots/pneumatic_finger.json")
        with self.assertRaisesRegex(ValueError, r"actuation\.pressure: .*got 150000"):
            finger.solve(actuation=cosserat.Actuation(pressure=1.5e5))
        with self.assertRaisesRegex(AttributeError, "no field 'tension'"):
            cosserat.Actuation(tension=[1.0])
        with self.assertRaisesRegex(AttributeError, "no field 'tension'"):
            only_tension.tension = [1.0]

    def test_static_solver_uses_the_problem_base_and_loads(self):
        # Clamp moved and turned in the file: the solver's default is the file's, as the CLI's.
        p = wire("statics", {"base": {"position": [1, 2, 3],
                                      "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
                             "loads": {"gravity": [0, 0, -9.81]}})
        solver = cosserat.StaticSolver(p)
        self.assertTrue(solver.solve().converged)
        np.testing.assert_allclose(solver.state()["position"][-1],
                                   cosserat.solve(p)["result"]["tip"]["position"], atol=1e-12)


class SolveLikeTheCommand(unittest.TestCase):
    """cosserat.solve runs any problem through the CLI's own runners."""

    def test_pinned_column_buckles_at_euler_with_the_shear_correction(self):
        # P_cr / (pi^2 EI / L^2) - 1 = (pi^2 r^2 / 4 L^2)(1 - E / kappa G) to first order in
        # (r/L)^2 (Engesser and axial shortening; docs/buckling.md): -1.81e-5 for this wire
        # (kappa = 0.882). 10 % of it: the estimate's own next order (the C++ test holds 5 % at
        # r/L = 1/200); measured -1.75e-5.
        p = wire("buckling", {"boundary": "pinned-pinned",
                              "buckling": {"load": "tip_force", "direction": [0, 0, -1],
                                           "max": 10.0}})
        out = cosserat.solve(p)
        self.assertTrue(out["converged"], out["log"])
        ratio = out["result"]["buckling"]["critical_load"] / (math.pi**2 * EI / L**2)
        estimate = math.pi**2 * R**2 / (4 * L**2) * (1 - E / (0.882 * G))
        self.assertAlmostEqual(ratio - 1, estimate, delta=0.1 * abs(estimate))

    def test_cantilever_modes_are_euler_bernoulli(self):
        # The straight wire's bending pairs at beta L = 1.8751 and 4.6941. Rotary inertia and
        # shear lower them by O((beta r / L)^2): 1e-5 and 9e-5 (measured -4.5e-6, -6.3e-5).
        out = cosserat.solve(wire("modes", {"modes": {"count": 4}}))
        self.assertTrue(out["converged"], out["log"])
        measured = out["result"]["modes"]["frequencies_hz"]
        for f, beta in zip(measured, [BETA_L[0], BETA_L[0], BETA_L[1], BETA_L[1]]):
            expected = beta**2 / (2 * math.pi * L**2) * math.sqrt(EI / RHO_A)
            self.assertAlmostEqual(f / expected, 1.0, delta=3e-4)

    def test_quaternion_fd_statics_agrees_with_se3(self):
        # The two formulations of one rod under a tip load (PL^2/EI = 0.5): the quaternion-FD
        # grid is second order in the segment length, ~(1/40)^2 / 12 = 5e-5 L here (measured
        # 4.9e-5 L); 2e-4 L.
        loads = {"tip_force": [-0.5 * EI / L**2, 0, 0]}
        fd = cosserat.solve(wire("statics", {"formulation": "quaternion-fd", "loads": loads}))
        se3 = cosserat.solve(wire("statics", {"loads": loads}), nodes=True)
        self.assertTrue(fd["converged"] and se3["converged"])
        gap = np.subtract(fd["result"]["tip"]["position"], se3["result"]["tip"]["position"])
        self.assertLess(np.linalg.norm(gap), 2e-4 * L)
        self.assertIn("quaternion-fd", fd["log"])
        self.assertEqual(len(se3["nodes_csv"].strip().splitlines()), 1 + 41)  # header + nodes

    def test_taut_wire_sags_as_the_tensioned_beam(self):
        # examples/taut_wire.json: pinned-pinned, tension T = 50 N, own weight w = rho A g:
        # EI y'''' - T y'' = w, mid-span sag w L^2/8T - (w EI/T^2)(1 - 1/cosh(kL/2)). The rod
        # also stretches by T/EA = 8e-5, lengthening the loaded span (measured +8.7e-5); shear
        # adds ~2e-5. 5e-4.
        out = cosserat.solve(cosserat.load_problem("examples/taut_wire.json"), nodes=True)
        self.assertTrue(out["converged"], out["log"])
        rows = np.array([line.split(",") for line in out["nodes_csv"].splitlines()[1:]], float)
        middle = rows[len(rows) // 2]
        self.assertAlmostEqual(middle[0], L / 2, delta=1e-3 * L)  # s
        w, T = RHO_A * 9.81, 50.0
        k = math.sqrt(T / EI)
        sag = w * L**2 / (8 * T) - w * EI / T**2 * (1 - 1 / math.cosh(k * L / 2))
        self.assertAlmostEqual(-middle[3] / sag, 1.0, delta=5e-4)  # z: gravity along -z

    def test_assigned_loads_are_checked(self):
        p = wire()
        loads = cosserat.Loads()
        loads.gravity = [0, math.nan, 0]
        p.loads = loads  # Problem.loads is assignable: solve() checks it like a file
        with self.assertRaisesRegex(ValueError, "loads"):
            cosserat.solve(p)

    def test_unsupported_problems_are_refused(self):
        with self.assertRaisesRegex(ValueError, "boundary"):
            cosserat.solve(wire("dynamics", {"formulation": "quaternion-fd",
                                             "boundary": "pinned-pinned"}))


class Assemblies(unittest.TestCase):
    def test_stewart_gough_inverse_then_forward_returns_the_pose(self):
        # Inverse kinematics of robots/stewart_gough.json, then forward kinematics at the lengths
        # it found: the platform returns to the file's pose within 1e-6 m and 1e-6 rad (both
        # solves converge to 1e-10 of their scales; the pose returns to ~1e-10 m,
        # tests/test_assembly_io.cpp).
        with open("robots/stewart_gough.json") as f:
            problem = json.load(f)
        inverse = cosserat.solve(cosserat.parse_problem(json.dumps(problem)))
        self.assertTrue(inverse["converged"], inverse["log"])
        self.assertEqual(inverse["result"]["assembly"]["kind"], "inverse")
        lengths = [rod["length"] for rod in inverse["result"]["assembly"]["rods"]]
        self.assertEqual(len(lengths), 6)
        target = problem["assembly"].pop("inverse")["poses"][0]
        problem["assembly"]["lengths"] = lengths
        forward = cosserat.solve(cosserat.parse_problem(json.dumps(problem)))
        self.assertTrue(forward["converged"], forward["log"])
        body = forward["result"]["assembly"]["bodies"][0]
        self.assertEqual(body["name"], "platform")
        dp = np.linalg.norm(np.array(body["position"]) - np.array(target["position"]))
        # |R0^T R - I|_F = 2 sqrt(2) sin(angle / 2) ~ sqrt(2) angle for a small angle.
        turn = np.linalg.norm(np.array(target["rotation"]).T @ np.array(body["rotation"])
                              - np.eye(3)) / math.sqrt(2)
        self.assertLess(dp, 1e-6)
        self.assertLess(turn, 1e-6)
        self.assertEqual(np.array(forward["result"]["assembly"]["pose_jacobian"]).shape, (6, 6))


class BendRadius(unittest.TestCase):
    def test_a_braked_tail_halves_the_vines_wrinkling_moment(self):
        # The tail pulled back to a braked reel carries T = p A / 2 and leaves the wall p A - T,
        # so the wrinkling moment (p A - T) r / 2 halves and bends nothing: the smallest radius
        # EI/M_w doubles (to 1e-5, the bisection's), and the plain tube grown under its own
        # weight first kinks at the first growth step past q L^2 / 2 = M_w, L = sqrt(2 M_w / q):
        # 0.832 m with the tail, 1.177 m without (0.02 m steps; the sag shortens the base
        # moment's lever by under 1e-3 of L, clear of the steps).
        p = cosserat.load_problem("robots/eversion_banded_vine.json")
        EI, _ = p.section_stiffness
        pull = math.pi * 3000.0 * 0.025 ** 2  # p A, N
        plain = EI / (pull * 0.025 / 2)
        with open("robots/eversion_banded_vine.json") as f:
            spec = json.load(f)
        spec["robot"]["tail_tension"] = pull / 2
        r = cosserat.minimum_bend_radius(spec, {"tip_moment": [0, 0, 1.0]}, length=0.6,
                                         bands=False)
        self.assertEqual(r["limit"], "kink")
        self.assertAlmostEqual(r["min_radius"] / (2 * plain), 1.0, delta=1e-5)
        del spec["rod"]["stiffness_profile"]["constrictions"]
        spec["rod"]["length"], spec["robot"]["growth"]["steps"] = 1.5, 70
        q = 920 * 2 * math.pi * 0.025 * 75e-6 * 9.81  # weight per length, N/m
        for tail in (pull / 2, 0.0):
            spec["robot"]["tail_tension"] = tail
            robot = cosserat.solve(spec)["result"]["robot"]
            self.assertEqual(robot["tail_tension"], tail)
            onset = math.sqrt((pull - tail) * 0.025 / q)
            self.assertGreaterEqual(robot["first_kink_length"], onset)
            self.assertLess(robot["first_kink_length"], onset + 0.02)

    def test_the_vine_kinks_at_the_radius_ei_over_its_wrinkling_moment(self):
        # The vine robot at 0.6 m under gravity, steered by a tip moment about the vertical: it
        # kinks where the moment reaches the wrinkling moment M_w = pi p r^3 / 2 (Suulker et al.
        # 2026), so its smallest radius is EI/M_w of the kinking section: the plain tube's at its
        # base, and with the bands (radius r/2, stiffness 0.36 E_eff I(r/2): M_w and I both fall
        # by 8) 0.36 times it at the first band (s = 0.3 m). To 1e-5 at the base: the kink is
        # bisected to 1e-6 in the load factor. At the band to 1e-3: there M_w = N r/2 also
        # counts the weight's share along the drooping tube in the wall force N, 1.5e-4 of the
        # band's pressure force p pi (r/2)^2 (measured).
        p = cosserat.load_problem("robots/eversion_banded_vine.json")
        EI, _ = p.section_stiffness
        plain = EI / (math.pi * 3000.0 * 0.025 ** 3 / 2)
        r = cosserat.minimum_bend_radius(p, {"tip_moment": [0, 0, 1.0]}, length=0.6, bands=False)
        self.assertEqual(r["limit"], "kink")
        self.assertAlmostEqual(r["min_radius"] / plain, 1.0, delta=1e-5)
        banded = cosserat.minimum_bend_radius(p, {"tip_moment": [0, 0, 1.0]}, length=0.6)
        self.assertEqual(banded["limit"], "kink")
        self.assertAlmostEqual(banded["min_radius"] / (0.36 * plain), 1.0, delta=1e-3)
        self.assertAlmostEqual(banded["s"], 0.3, delta=1e-9)
        with self.assertRaisesRegex(ValueError, "robot.kind: the minimum bend radius is an "
                                    "eversion robot's"):
            cosserat.minimum_bend_radius("robots/tendon_three_tendon.json", {"tip_force": [1, 0, 0]})
        with self.assertRaisesRegex(ValueError, "pattern.gravity: unknown key"):
            cosserat.minimum_bend_radius(p, {"gravity": [0, 0, -9.81]})
        with self.assertRaisesRegex(ValueError, r"length: expected an everted length in \(0, "):
            cosserat.minimum_bend_radius(p, {"tip_moment": [0, 0, 1.0]}, length=2.0)
        # At 1.2 m the plain tube's own weight bends its base by about q L^2/2 = 1.04 M_w
        # (q = 0.1063 N/m, M_w = 0.0736 N m): kinked before any steering, which the result
        # says (it once bisected down to a "kink" at load factor 0 with a folded tube's radius).
        q = 920 * 2 * math.pi * 0.025 * 75e-6 * 9.81
        self.assertGreater(q * 1.2 ** 2 / 2 / (math.pi * 3000.0 * 0.025 ** 3 / 2), 1.0)
        with self.assertWarnsRegex(RuntimeWarning, "the problem's loads alone kink the tube"):
            folded = cosserat.minimum_bend_radius(p, {"tip_moment": [0, 0, 1.0]}, length=1.2,
                                                  bands=False)
        self.assertEqual(folded["limit"], "kinked_by_fixed_loads")
        self.assertEqual(folded["load_factor"], 0.0)
        self.assertGreater(folded["kink_ratio"], 1.0)


class PythonSide(unittest.TestCase):
    """The package's Python side: problems as dicts and paths, NumPy results, plot, animate."""

    def test_a_dict_solves_like_its_file_and_gives_numpy_arrays(self):
        # The elastica at alpha = 1 (Bisshopp & Drucker 1945): tip deflection 0.3017207738 L;
        # the wire's extension and shear move it by ~(r/L)^2 = 4e-6.
        out = cosserat.solve(wire(extra={"loads": {"tip_force": [-EI / L**2, 0, 0]}}))
        self.assertTrue(out["converged"])
        nodes = out["nodes"]["position"]
        self.assertIsInstance(nodes, np.ndarray)
        self.assertEqual(nodes.shape, (41, 3))
        self.assertAlmostEqual(-nodes[-1, 0] / L, 0.3017207738, delta=2e-5)
        from_file = cosserat.solve("examples/cantilever.json")
        self.assertTrue(from_file["converged"])
        with self.assertRaises(TypeError):
            cosserat.solve(42)
        with self.assertRaisesRegex(ValueError, "rod.length: expected a positive number"):
            cosserat.solve(wire(extra={"rod": {"length": -1, "nodes": 41,
                                               "section": {"shape": "circle", "radius": R},
                                               "material": {"youngs_modulus": E,
                                                            "shear_modulus": G,
                                                            "density": RHO}}}))
        # A NaN or an object in the dict is named where it is (JSON has no NaN: written out, it
        # would be a parse error at a column of the text).
        bad = wire_spec(extra={"loads": {"tip_force": [float("nan"), 0, 0]}})
        with self.assertRaisesRegex(ValueError, r"loads.tip_force\[0\]: expected a finite number"):
            cosserat.solve(bad)
        with self.assertRaisesRegex(TypeError, "loads.gravity: expected a JSON value"):
            cosserat.solve(wire_spec(extra={"loads": {"gravity": object()}}))
        # NumPy values are numbers and booleans like any other.
        spec = wire_spec(extra={"loads": {"tip_force": np.array([-EI / L**2, 0.0, 0.0])}})
        spec["rod"]["nodes"] = np.int64(41)
        self.assertTrue(cosserat.solve(spec)["converged"])
        spec["solver"] = {"tolerance": np.float64(1e-10), "max_iterations": np.int32(50)}
        self.assertTrue(cosserat.solve(spec)["converged"])

    def test_frames_plot_and_animate(self):
        import matplotlib
        matplotlib.use("Agg")
        import tempfile
        from PIL import Image
        out = cosserat.solve("tests/vtk/release_2s.json", nodes=True)
        frames = out["frames"]
        # The frames are the trajectory's: 41 times, the tip of each is the trajectory's tip.
        self.assertEqual(frames["position"].shape, (41, 21, 3))
        np.testing.assert_array_equal(frames["t"], out["trajectory"]["t"])
        np.testing.assert_allclose(frames["position"][:, -1, :], out["trajectory"]["tip_position"],
                                   rtol=0, atol=1e-15)
        # The envelope, one value per node, bounds the final state's bending moment.
        moment = np.hypot(out["nodes"]["moment_body"][:, 0], out["nodes"]["moment_body"][:, 1])
        self.assertEqual(out["envelope"]["moment_max"].shape, (21,))
        self.assertTrue(np.all(out["envelope"]["moment_max"] >= moment))
        ax = cosserat.plot(out)
        self.assertEqual(len(ax.lines), 3)  # the rod, its base, the tip's path
        with tempfile.TemporaryDirectory() as d:
            gif = d + "/release.gif"
            written = cosserat.animate(out, gif, every=4)
            self.assertEqual(written, 11)
            with Image.open(gif) as image:
                self.assertEqual(image.n_frames, 11)
            # MP4 through ffmpeg (Debian's ffmpeg, install-deps.sh --test): ffprobe counts the
            # frames written.
            mp4 = d + "/release.mp4"
            self.assertEqual(cosserat.animate(out, mp4, every=4), 11)
            probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams",
                                    "v:0", "-show_entries", "stream=nb_read_frames", "-of",
                                    "csv=p=0", mp4], stdout=subprocess.PIPE, text=True, check=True)
            self.assertEqual(int(probe.stdout.strip()), 11)
            # WebM takes VP9 (it was given H.264, which ffmpeg refuses in that container).
            webm = d + "/release.webm"
            self.assertEqual(cosserat.animate(out, webm, every=4), 11)
            probe = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0",
                                    "-show_entries", "stream=codec_name", "-of", "csv=p=0", webm],
                                   stdout=subprocess.PIPE, text=True, check=True)
            self.assertEqual(probe.stdout.strip(), "vp9")
        with self.assertRaisesRegex(ValueError, "nodes=True"):
            cosserat.animate(cosserat.solve("examples/cantilever.json"), "x.gif")
        # A run whose start cannot converge (a 1e300 N preload) records no frame: a result that
        # says so, as without nodes=True (it raised IndexError on the header-only table).
        with open("examples/cantilever_release.json") as f:
            spec = json.load(f)
        spec["dynamics"]["duration"] = 0.02
        spec["dynamics"]["initial_loads"]["tip_force"] = [1e300, 0, 0]
        failed = cosserat.solve(spec, nodes=True)
        self.assertFalse(failed["converged"])
        self.assertNotIn("frames", failed)


    def test_static_solver_gives_tendon_lengths_and_the_tension_jacobian(self):
        # The lengths are the CLI's robot.tendon_length; the Jacobian's position rows match
        # central differences of the tip in each tension (step 1e-3 N on 1.5 N: truncation
        # ~1e-7 of the column, the solves' 1e-10 noise / 2e-3 N ~5e-8: 1e-5 relative bounds both).
        p = cosserat.load_problem("robots/tendon_three_tendon.json")
        s = cosserat.StaticSolver(p)
        self.assertEqual(s.solve().status, "converged")
        cli = cosserat.solve("robots/tendon_three_tendon.json")["result"]["robot"]["tendon_length"]
        np.testing.assert_allclose(s.tendon_lengths, cli, rtol=0, atol=1e-15)
        # Every tendon taut (differences both ways), then the Jacobian there.
        tension = np.array([1.5, 0.5, 0.5])
        a = p.actuation
        a.tendon_tension = list(tension) + [0.0] * (len(a.tendon_tension) - 3)
        self.assertEqual(s.solve(actuation=a).status, "converged")
        J = s.tension_jacobian()
        self.assertEqual(J.shape, (6, 3))
        h = 1e-3
        for i in range(3):
            tips = []
            for sign in (1, -1):
                a = p.actuation
                t = tension.copy()
                t[i] += sign * h
                a.tendon_tension = list(t) + [0.0] * (len(a.tendon_tension) - 3)
                self.assertEqual(s.solve(actuation=a).status, "converged")
                tips.append(s.state()["position"][-1])
            fd = (tips[0] - tips[1]) / (2 * h)
            np.testing.assert_allclose(J[:3, i], fd, rtol=1e-5, atol=1e-5 * np.abs(J[:3]).max())

    def test_reprs_show_the_values(self):
        # What a notebook prints: the file's values, not object addresses.
        p = cosserat.load_problem("robots/tendon_three_tendon.json")
        self.assertIn("tendon_tension=[1.5, 0, 0.5]", repr(p.actuation))
        # A list at the length it was given, trailing zeros too.
        given = cosserat.Actuation(tendon_tension=[1, 0, 0])
        self.assertIn("tendon_tension=[1, 0, 0]", repr(given))
        self.assertIn("length=0.25 m", repr(p))
        current = cosserat.load_problem("examples/cantilever_in_current.json")
        self.assertIn("Fluid(density=1025, velocity=[0.8, 0, 0]", repr(current.loads))
        solver = cosserat.StaticSolver(p)
        summary = solver.solve()
        self.assertTrue(repr(summary).startswith("StaticSummary(status=converged"))
        self.assertIn("nodes=", repr(solver))
        stepper = cosserat.Stepper(wire("dynamics"))
        self.assertIn("dt=", repr(stepper))
        self.assertIn("time=0 s", repr(stepper))

    def test_live_view_damps_every_section_shape(self):
        # The live view adds 0.05 s of bending and torsion damping when a file has none, from the
        # section's EI and GJ: circle and annulus π(r_o⁴ − r_i⁴)/4 (J twice that), a rectangle
        # w h³/12 about its weak axis with Roark's J, an explicit section's smaller I and its J.
        from cosserat.view import LiveRod, _section_stiffness
        mat = {"youngs_modulus": 1e9, "shear_modulus": 4e8}
        ei, gj = _section_stiffness({"section": {"shape": "annulus", "outer_radius": 0.01,
                                                 "inner_radius": 0.009}, "material": mat})
        i_annulus = math.pi * (0.01**4 - 0.009**4) / 4
        self.assertAlmostEqual(ei / (1e9 * i_annulus), 1.0, places=12)
        self.assertAlmostEqual(gj / (4e8 * 2 * i_annulus), 1.0, places=12)
        ei, gj = _section_stiffness({"section": {"shape": "rectangle", "width": 0.02,
                                                 "height": 0.002}, "material": mat})
        self.assertAlmostEqual(ei / (1e9 * 0.02 * 0.002**3 / 12), 1.0, places=12)
        j = 0.02 * 0.002**3 * (1 / 3 - 0.21 * 0.1 * (1 - 0.1**4 / 12))
        self.assertAlmostEqual(gj / (4e8 * j), 1.0, places=12)
        ei, gj = _section_stiffness({"section": {"area": 1e-4, "I1": 2e-9, "I2": 1e-9,
                                                 "J": 3e-9}, "material": mat})
        self.assertEqual((ei, gj), (1e9 * 1e-9, 4e8 * 3e-9))
        live = LiveRod("robots/jamming_virtual_joints.json")  # an annulus without damping
        try:
            self.assertTrue(any("damping" in note for note in live.config()["notes"]))
        finally:
            live.running = False
            live.thread.join(10)  # not stepping in C++ while the interpreter shuts down
        # An inflated tube's tip-force range from its profile's EI (3 EI/L² ≈ 1 N), not from the
        # solid 25 mm circle its section names (±64 N).
        ei, gj = cosserat.load_problem("robots/eversion_banded_vine.json").section_stiffness
        live = LiveRod("robots/eversion_banded_vine.json")
        try:
            tip = next(c for c in live.config()["controls"] if c["name"] == "tip_force_x")
            self.assertAlmostEqual(tip["max"], max(3 * ei / 1.2**2, 0.0), places=9)
            self.assertLess(tip["max"], 2.0)
        finally:
            live.running = False
            live.thread.join(10)

    def test_live_view_inflates_the_vine_and_shows_the_values_that_act(self):
        # The vine's fold at its band (|m|/M_w = 4.65, as the command line reports it) shows in
        # the view's status; its inflation slider re-solves it at the pressure set (its section's
        # pressure follows, as the file's rule asks), and the controls read back as set.
        import time
        from cosserat.view import LiveRod
        cli = cosserat.solve("robots/eversion_banded_vine.json")["result"]["robot"]["kink"]
        live = LiveRod("robots/eversion_banded_vine.json")
        try:
            deadline = time.time() + 30
            while time.time() < deadline and "converged" not in live.snapshot()["status"]:
                time.sleep(0.05)
            self.assertIn(f"collapsed (|m|/M_w = {cli['max_moment_ratio']:.3g} at s = "
                          f"{cli['s_max']:g} m)", live.snapshot()["status"])
            self.assertIsNone(live.set_control("inflation", 4000.0))
            version = live.control_version
            deadline = time.time() + 30
            while time.time() < deadline and live.snapshot().get("control_version") != version:
                time.sleep(0.05)
            snap = live.snapshot()
            self.assertEqual(snap.get("control_version"), version)
            self.assertNotIn("refused", snap["status"])
            inflation = next(c for c in live.config()["controls"] if c["name"] == "inflation")
            self.assertEqual(inflation["value"], 4000.0)
        finally:
            live.running = False
            live.thread.join(10)

    def test_live_view_draws_a_strip_at_its_equal_area_radius(self):
        # A 4 mm × 2 mm strip is drawn as a tube of its area's radius sqrt(w h / π) (the VTK
        # output's), not at a 5 mm default.
        import tempfile
        from cosserat.view import LiveRod
        spec = {"format": "cosserat-problem/1", "analysis": "dynamics",
                "rod": {"length": 0.2, "nodes": 11,
                        "section": {"shape": "rectangle", "width": 0.004, "height": 0.002},
                        "material": {"youngs_modulus": 1e9, "shear_modulus": 4e8,
                                     "density": 1000}},
                "dynamics": {"dt": 1e-3, "duration": 1.0}}
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump(spec, f)
        live = LiveRod(f.name)
        try:
            self.assertAlmostEqual(live.config()["radius"], math.sqrt(0.004 * 0.002 / math.pi),
                                   places=15)
        finally:
            live.running = False
            live.thread.join(10)
            os.unlink(f.name)

    def test_assemblies_are_plotted_and_animated_rod_by_rod(self):
        # The plate on two wires: its frames hold each rod's nodes, which end where the run's
        # result puts them; plot draws both rods and the plate, animate writes every frame.
        import matplotlib
        matplotlib.use("Agg")
        import tempfile
        out = cosserat.solve("examples/platform_release.json", nodes=True)
        self.assertTrue(out["converged"], out["log"])
        rods = out["frames"]["rods"]
        self.assertEqual(len(rods), 2)
        for frames, rod in zip(rods, out["result"]["assembly"]["rods"]):
            self.assertEqual(frames.shape, (len(out["frames"]["t"]), 21, 3))
            np.testing.assert_allclose(frames[-1], rod["nodes"]["position"], rtol=0, atol=1e-15)
        ax = cosserat.plot(out)
        self.assertEqual(len(ax.lines), 2 * 2 + 1)  # each rod and its base, the plate
        with tempfile.TemporaryDirectory() as d:
            self.assertEqual(cosserat.animate(out, d + "/plate.gif", every=100),
                             len(out["frames"]["t"][::100]))
        with self.assertRaisesRegex(ValueError, "every"):
            cosserat.animate(out, "x.gif", every=0)
        with self.assertRaisesRegex(ValueError, "path"):
            cosserat.animate(out, "x.png")


class Batches(unittest.TestCase):
    """cosserat.BatchStepper and cosserat.sweep."""

    def test_a_failed_rod_is_named_and_stays_behind(self):
        # Two peer wires, the second pulled with 10 kN (its step cannot converge): the count says
        # one converged, converged() says which, and the failed rod keeps its state at t = 0
        # while the other is one dt on.
        p = cosserat.load_problem("examples/cantilever_release.json")
        batch = cosserat.BatchStepper(p, 2, threads=1)
        self.assertEqual(batch.initialize_at_rest(), 2)
        self.assertEqual(batch.step(tip_force=np.array([[0.0, 0, 0], [1e4, 0, 0]])), 1)
        self.assertEqual(batch.converged(), [True, False])
        self.assertEqual(batch.times, [p.dt, 0.0])

    def test_two_threads_on_one_batch_take_turns(self):
        # step() lets go of the GIL while the rods run; a second thread stepping the same batch
        # then corrupted the heap (an abort). Now calls wait their turn: two threads of 150
        # steps each and a third reading the times meanwhile all run, and the rods' time counts
        # exactly the 300 steps (none lost, none half-done).
        import threading
        p = cosserat.load_problem("examples/cantilever_release.json")
        batch = cosserat.BatchStepper(p, 8, threads=1)
        self.assertEqual(batch.initialize_at_rest(), 8)
        errors, seen = [], []

        def step():
            try:
                for _ in range(150):
                    batch.step()
            except Exception as e:  # noqa: BLE001  (any error is the test's failure)
                errors.append(e)

        def read():
            try:
                for _ in range(150):
                    seen.append(batch.times[0])
            except Exception as e:  # noqa: BLE001
                errors.append(e)
        threads = [threading.Thread(target=f) for f in (step, step, read)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(errors, [])
        np.testing.assert_allclose(batch.times, [300 * p.dt] * 8, rtol=1e-12)
        self.assertEqual(seen, sorted(seen))  # each read saw whole steps, in order

    def test_64_rods_step_exactly_as_64_steppers(self):
        # The peer release's wire, 64 rods each with its own tip-force history: every rod's tip
        # is bitwise the one a lone Stepper reaches with the same inputs (the threads only share
        # out the rods).
        p = cosserat.load_problem("examples/cantilever_release.json")
        M, steps = 64, 10
        batch = cosserat.BatchStepper(p, M, threads=2)
        self.assertEqual(batch.initialize_at_rest(), M)
        lone = [cosserat.Stepper(p) for _ in range(M)]
        for s in lone:
            self.assertTrue(s.initialize_at_rest().converged)
        for k in range(steps):
            forces = np.array([[-0.01 * (i % 8), 1e-3 * k * (i % 3), 0.0] for i in range(M)])
            self.assertEqual(batch.step(tip_force=forces), M)
            for i, s in enumerate(lone):
                loads = s.loads
                loads.tip_force = forces[i]
                self.assertTrue(s.step(loads=loads).converged)
        tips = batch.tip_positions()
        self.assertEqual(tips.shape, (M, 3))
        for i, s in enumerate(lone):
            np.testing.assert_array_equal(tips[i], s.tip_position())
        with self.assertRaisesRegex(ValueError, r"tip_force: expected shape \(64, 3\)"):
            batch.step(tip_force=np.zeros((3, 3)))
        # No state before initialize_at_rest (no zeros passed off as tips), and no more threads
        # than rods whatever is asked (a million asked for here).
        fresh = cosserat.BatchStepper(p, 2, threads=10**6)
        with self.assertRaisesRegex(RuntimeError, "initialize_at_rest"):
            fresh.tip_positions()
        with self.assertRaisesRegex(RuntimeError, "initialize_at_rest"):
            fresh.step()
        self.assertEqual(fresh.initialize_at_rest(), 2)
        self.assertEqual(fresh.tip_positions().shape, (2, 3))

    def test_rollouts_from_a_steppers_snapshot_continue_its_run(self):
        # A sampling controller: the measured rod (a Stepper pushed by 0.02 N for 8 steps) is
        # copied into 3 rods, and rod i rolled out under its own force must reach exactly what
        # the Stepper, never interrupted, reaches under it. step() with nothing given keeps the
        # measured run's force, as the Stepper does.
        p = cosserat.load_problem("examples/cantilever_release.json")
        measured = cosserat.Stepper(p)
        self.assertTrue(measured.initialize_at_rest().converged)
        loads = measured.loads
        loads.tip_force = np.array([0.0, 0.02, 0.0])
        for _ in range(8):
            self.assertTrue(measured.step(loads=loads).converged)
        snapshot = measured.save()
        batch = cosserat.BatchStepper(p, 3, threads=2)
        batch.restore(snapshot)
        self.assertEqual(batch.times, [measured.time] * 3)
        self.assertEqual(batch.step(), 3)
        forces = np.array([[0.0, 0.02 * i, -0.01 * i] for i in range(3)])
        self.assertEqual(batch.step(tip_force=forces), 3)
        for i in range(3):
            lone = cosserat.Stepper(p)
            lone.restore(snapshot)
            self.assertTrue(lone.step().converged)
            loads.tip_force = forces[i]
            self.assertTrue(lone.step(loads=loads).converged)
            np.testing.assert_array_equal(batch.tip_positions()[i], lone.tip_position())
        # positions(): every node, the tip last.
        nodes = batch.positions()
        self.assertEqual(nodes.shape, (3, p.nodes, 3))
        np.testing.assert_array_equal(nodes[:, -1, :], batch.tip_positions())
        # save() and restore() of the batch repeat its run bit for bit.
        saved = batch.save()
        self.assertEqual(len(saved), 3)
        first = [batch.step(tip_force=forces), batch.tip_positions()]
        batch.restore(saved)
        again = [batch.step(tip_force=forces), batch.tip_positions()]
        self.assertEqual(first[0], again[0])
        np.testing.assert_array_equal(first[1], again[1])
        # A wrong count, or a snapshot of another grid: ValueError, and no rod moves.
        before = batch.tip_positions()
        with self.assertRaisesRegex(ValueError, "expected 3 snapshots, got 2"):
            batch.restore(saved[:2])
        with open("examples/cantilever_release.json") as f:
            spec = json.load(f)
        spec["rod"]["nodes"] += 10
        other = cosserat.Stepper(spec)
        self.assertTrue(other.initialize_at_rest().converged)
        with self.assertRaisesRegex(ValueError, "another grid"):
            batch.restore(saved[:2] + [other.save()])
        np.testing.assert_array_equal(batch.tip_positions(), before)
        with self.assertRaisesRegex(RuntimeError, "initialize_at_rest"):
            cosserat.BatchStepper(p, 2, threads=1).save()

    def test_ctrl_c_stops_a_long_solve_and_a_sweep(self):
        # SIGINT (Ctrl-C, Jupyter's interrupt) half a second in: the run stops within its next
        # 0.1 s check and raises KeyboardInterrupt instead of running to its end (a 2000 s
        # release: ~8 s here; 10 000 sweep points: ~10 s). The sweep keeps the rows it wrote.
        import signal
        import tempfile
        import threading
        import time

        def interrupt_soon():
            threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()

        def interrupted(path, change):
            with open(path) as f:
                spec = json.load(f)
            change(spec)
            interrupt_soon()
            t0 = time.monotonic()
            with self.assertRaises(KeyboardInterrupt):
                cosserat.solve(spec)
            self.assertLess(time.monotonic() - t0, 4.0)

        interrupted("examples/cantilever_release.json",
                    lambda spec: spec["dynamics"].update(duration=2000.0))
        # Quaternion-FD dynamics asks after every Radau step, not only at its frames: here one
        # output interval of 100 s holds ~60 s of steps.
        interrupted("examples/cantilever_release.json",
                    lambda spec: (spec.update(formulation="quaternion-fd"),
                                  spec["dynamics"].update(duration=500.0, output_interval=100.0)))
        # So does an SE(3) modes scan (the steel wire on 10 001 nodes: ~40 s to its end).
        interrupted("examples/modes_cantilever.json", lambda spec: spec["rod"].update(nodes=10001))
        study = {"format": "cosserat-study/1", "problem": "examples/cantilever.json",
                 "parameters": [{"path": "/loads/tip_force/0",
                                 "values": [-0.5 + 1e-4 * i for i in range(10000)]}],
                 "outputs": {"tip_x": "/tip/position/0"}}
        with tempfile.TemporaryDirectory() as d:
            interrupt_soon()
            t0 = time.monotonic()
            with self.assertRaises(KeyboardInterrupt):
                cosserat.sweep(study, out=d + "/rows.csv", threads=1)
            self.assertLess(time.monotonic() - t0, 4.0)
            with open(d + "/rows.csv") as f:
                rows = sum(1 for _ in f) - 1  # the header
            self.assertGreater(rows, 0)
            self.assertLess(rows, 10000)

    def test_sweep_rows_are_the_solves_of_their_points(self):
        # Each row of a small study is what solving its point alone gives.
        study = {"format": "cosserat-study/1", "problem": "examples/cantilever.json",
                 "parameters": [{"path": "/loads/tip_force/0", "values": [-0.2, 0.0, 0.3]}],
                 "outputs": {"tip_x": "/tip/position/0", "tip": "/tip/position",
                             "warnings": "/warnings"}}
        import glob
        import tempfile
        mine = os.path.join(tempfile.gettempdir(), "cosserat_sweep_*")
        before = set(glob.glob(mine))
        out = cosserat.sweep(study, threads=np.int64(2))  # a NumPy integer is a whole number
        self.assertTrue(out["summary"]["complete"])
        self.assertIsNone(out["csv"])  # no out=: the temporary files are gone, all of them
        self.assertEqual(set(glob.glob(mine)) - before, set())
        self.assertEqual([r["index"] for r in out["rows"]], [0, 1, 2])
        for row in out["rows"]:
            with open("examples/cantilever.json") as f:
                spec = json.load(f)
            spec["loads"]["tip_force"][0] = row["/loads/tip_force/0"]
            alone = cosserat.solve(spec)["result"]["tip"]["position"]
            self.assertEqual(row["tip_x"], alone[0])
            # A list output is an array (the CSV holds it as JSON text).
            np.testing.assert_array_equal(row["tip"], alone)
            self.assertEqual(row["status"], "converged")
            # The log's warnings, a list (none for the example's steel cantilever).
            self.assertEqual(row["warnings"], cosserat.solve(spec)["result"]["warnings"])
            self.assertEqual(row["warnings"], [])
        with self.assertRaisesRegex(ValueError, "parameters\\[0\\].path"):
            cosserat.sweep(dict(study, parameters=[{"path": "/nope/x", "values": [1]}]))
        for threads in (0, -1, 1.5):
            with self.assertRaisesRegex(ValueError, "threads: expected a whole number"):
                cosserat.sweep(study, threads=threads)
        with self.assertRaisesRegex(ValueError, r"parameters\[0\].values\[0\]: expected a finite"):
            cosserat.sweep(dict(study, parameters=[{"path": "/loads/tip_force/0",
                                                    "values": [float("nan")]}]))
        with self.assertRaisesRegex(ValueError, "study: cannot read"):
            cosserat.sweep("no_such_study.json")
        with self.assertRaisesRegex(TypeError, "study: expected a dict"):
            cosserat.sweep(42)
        self.assertEqual(out["summary"]["empty_outputs"], [])
        # A pointer that names nothing in the result: a blank column, and a warning naming it.
        with self.assertWarnsRegex(UserWarning, r'"tip_x" \(/tip/positoin/0\) is empty'):
            typo = cosserat.sweep(dict(study, outputs={"tip_x": "/tip/positoin/0"}))
        self.assertEqual(typo["summary"]["empty_outputs"], ['"tip_x" (/tip/positoin/0)'])


if __name__ == "__main__":
    unittest.main()
