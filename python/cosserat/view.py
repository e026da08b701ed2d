"""The live browser view: `python3 -m cosserat.view PROBLEM.json [--port 8765] [--open]`.

A local server steps the problem's rod in real time and the page (web/index.html, three.js)
draws it; sliders (or dragging the tip with the mouse) change the tip force, move the base, and
set tendon tensions, chamber pressures, jamming and inflation pressures. Two modes, by what the
problem is:

  dynamics      a cantilever on the SE(3) path (any analysis): BDF2 steps of the problem's dt
                (2 ms by default), as many per 1/60 s frame as keep up with the wall clock. A
                rod whose material has no damping gets Kelvin–Voigt damping of 0.05 s on bending
                and torsion in the view, so that it settles; the page says so.
  quasi-static  anything else (the quaternion-FD path, held rods, assemblies): every change of
                a control re-solves the statics, as `cosserat solve` would.

HTTP: GET / (the page), GET /config (the controls and the mode), GET /state (the latest frame:
nodes, tip, status, real-time ratio), POST /control {"name": ..., "value": ...} (400 with a
message for an unknown control or a value outside its range). A problem file that cannot be
read still serves the page, which shows the error.
"""
import argparse
import collections
import copy
import json
import math
import os
import threading
import time
import webbrowser
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import numpy as np

from . import _core

FRAME_S = 1.0 / 60.0
VIEW_DAMPING_S = 0.05


def _web_dir():
    """The page's files: COSSERAT_WEB_DIR when set, else web/ of the repository this package
    was built or installed from; None when neither has index.html."""
    here = os.path.dirname(os.path.abspath(__file__))
    chosen = os.environ.get("COSSERAT_WEB_DIR")
    if chosen and not os.path.exists(os.path.join(chosen, "index.html")):
        # A directory the user named is theirs to mend, not to pass over for another copy.
        raise SystemExit(f"cosserat view: COSSERAT_WEB_DIR={chosen!r} has no index.html: set it "
                         "to the repository's web/ directory, or unset it")
    candidates = [chosen] if chosen else []
    candidates += [os.path.join(root, "web")
                   for root in (os.path.join(here, "..", "..", ".."), os.path.join(here, "..", ".."))]
    try:  # a pip-installed copy: setup.py recorded the repository it was built from
        from cosserat._source import SOURCE_DIR
        candidates.append(os.path.join(SOURCE_DIR, "web"))
    except (ImportError, SyntaxError):  # none, or written from a path it could not quote
        pass
    for web in candidates:
        if os.path.exists(os.path.join(web, "index.html")):
            return os.path.abspath(web)
    return None


def _section_stiffness(rod):
    """The smaller bending stiffness EI and the torsional stiffness GJ (N·m²) of the section a
    problem file gives (circle, annulus, rectangle or explicit), None when the file does not say
    enough (no shape, no modulus)."""
    sec, mat = rod.get("section", {}), rod.get("material", {})
    E = mat.get("youngs_modulus")
    if not E:
        return None
    G = mat.get("shear_modulus") or E / (2 * (1 + mat.get("poisson_ratio", 0.3)))
    shape = sec.get("shape") or ("explicit" if "I1" in sec else None)
    if shape in ("circle", "annulus"):
        ro = sec.get("radius") or sec.get("outer_radius")
        ri = sec.get("inner_radius", 0.0) if shape == "annulus" else 0.0
        if not ro:
            return None
        I = math.pi * (ro**4 - ri**4) / 4
        return E * I, G * 2 * I
    if shape == "rectangle":
        w, h = sec.get("width"), sec.get("height")
        if not (w and h):
            return None
        a, b = max(w, h), min(w, h)
        # Roark's torsion constant of a rectangle: a b³ (1/3 − 0.21 (b/a)(1 − b⁴/(12 a⁴))).
        J = a * b**3 * (1 / 3 - 0.21 * (b / a) * (1 - b**4 / (12 * a**4)))
        return E * a * b**3 / 12, G * J
    if shape == "explicit" and sec.get("I1") and sec.get("I2") and sec.get("J"):
        return E * min(sec["I1"], sec["I2"]), G * sec["J"]
    return None


def _section_area(rod):
    """The section's area (m²) from the problem file's shape, None when it does not say."""
    sec = rod.get("section", {})
    shape = sec.get("shape") or ("explicit" if "area" in sec else None)
    if shape in ("circle", "annulus"):
        ro = sec.get("radius") or sec.get("outer_radius") or 0.0
        ri = sec.get("inner_radius", 0.0) if shape == "annulus" else 0.0
        return math.pi * (ro**2 - ri**2) or None
    if shape == "rectangle":
        return (sec.get("width") or 0.0) * (sec.get("height") or 0.0) or None
    return sec.get("area") if shape == "explicit" else None


# Columns: the tip is held sideways, so only a tip force's axial part moves the rod and a
# uniform load is offered beside it.
COLUMN_BOUNDARIES = ("pinned-pinned", "clamped-clamped", "clamped-pinned")


# The problem file's actuation names and cosserat.Actuation's attributes for them.
ACTUATION_ATTRIBUTE = {"tension": "tendon_tension", "chamber_pressure": "chamber_pressure",
                       "jamming_pressure": "jamming_pressure", "pressure": "pressure"}


def _control_actuation(v, tendons, chambers, jammed):
    """The actuation the controls' values v set, by the problem file's names: tendon tensions,
    chamber pressures and jamming pressures (lists of the given lengths) and the inflation."""
    out = {}
    if tendons:
        out["tension"] = [v[f"tension_{i}"] for i in range(tendons)]
    if chambers:
        out["chamber_pressure"] = [v[f"pressure_{i}"] for i in range(chambers)]
    if jammed:
        out["jamming_pressure"] = [v[f"jamming_{i}"] for i in range(jammed)]
    if "inflation" in v:
        out["pressure"] = v["inflation"]
    return out


class LiveRod:
    """The problem, its controls and the simulation thread."""

    def __init__(self, path):
        self.path = path
        self.lock = threading.Lock()
        self.error = None
        self.controls = []
        self.values = {}
        self.control_version = 0
        self.state = {"frame": 0, "status": "starting", "rods": [], "tip": None,
                      "real_time_ratio": None, "t": 0.0, "control_version": 0}
        self.notes = []
        self.thread = None  # a problem that does not load shows its error and runs nothing
        try:
            with open(path) as f:
                self.spec = json.load(f)
            self.problem = _core.parse_problem(json.dumps(self.spec))
        except (OSError, ValueError) as e:
            self.error = f"{path}: {e}"
            self.mode = "none"
            return
        self._make_controls()
        try:  # the SE(3) stepper takes it (a cantilever, a tendon or pneumatic robot)?
            if "assembly" in self.spec:
                raise ValueError("an assembly")
            self.dynamic = _core.parse_problem(json.dumps(self._dynamic_problem()))
            _core.Stepper(self.dynamic)
            self.mode = "dynamics"
        except ValueError:
            self.mode, self.notes = "quasi-static", []
        if "inverse" in self.spec.get("assembly", {}):
            self.notes.append("inverse kinematics: the bodies stay at the file's poses, and a "
                              "force on them changes the rods' lengths, not the pose")
        if self.mode == "dynamics":
            L = self.spec.get("rod", {}).get("length", 1.0)
            self._add("base_x", "base position x", "m", -0.5 * L, 0.5 * L, 0.0)
            self._add("base_angle_y", "base turn about y", "rad", -1.5, 1.5, 0.0)
        self.running = True
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def stop(self):
        """Ends the simulation thread, waiting (5 s at most) until it is out of the solver: the
        interpreter must not shut down under a running C++ solve."""
        self.running = False
        if self.thread is not None:
            self.thread.join(5)

    # -- the problem ------------------------------------------------------------------------
    def _rod(self):
        """The rod whose scale sets the controls' ranges: the problem's, or an assembly's first."""
        if "assembly" in self.spec:
            rods = self.spec["assembly"].get("rods", [])
            return rods[0].get("rod", {}) if rods else {}
        return self.spec.get("rod", {})

    def _stiffness(self):
        """EI and GJ of the rod that sets the controls' ranges: from the solver's section law
        (stiffness profiles and pressure included: an inflated tube is far softer than the solid
        circle its section names) when the file is a valid single rod, else from the section."""
        if "assembly" not in self.spec:
            try:
                return _core.parse_problem(json.dumps(self.spec)).section_stiffness
            except ValueError:
                pass
        return _section_stiffness(self._rod())

    def _scale(self):
        rod = self._rod()
        L = rod.get("length", 1.0)
        stiff = self._stiffness()
        force = 3 * stiff[0] / L**2 if stiff else 1.0
        tip = np.linalg.norm(self.spec.get("loads", {}).get("tip_force", [0, 0, 0]))
        return L, max(force, 2 * tip)

    def _make_controls(self):
        L, force = self._scale()
        if "assembly" in self.spec:  # the first body's applied force
            body = (self.spec["assembly"].get("bodies") or [{}])[0]
            f = body.get("force", [0, 0, 0])
            for k, axis in enumerate("xyz"):
                self._add(f"body_force_{axis}", f"{body.get('name', 'body')} force {axis}", "N",
                          -force, force, f[k])
            return
        loads = self.spec.get("loads", {})
        anchored = "anchor" in self.spec  # the tip held in place: a tip force moves nothing
        if not anchored:
            tip = loads.get("tip_force", [0, 0, 0])
            for k, axis in enumerate("xyz"):
                self._add(f"tip_force_{axis}", f"tip force {axis}", "N", -force, force, tip[k])
        if anchored or self.spec.get("boundary") in COLUMN_BOUNDARIES:
            # A uniform load: ± the tip-force scale per metre, or twice the weight or the file's.
            rod = self._rod()
            area, rho = _section_area(rod), rod.get("material", {}).get("density", 0.0)
            weight = rho * (area or 0.0) * np.linalg.norm(loads.get("gravity", [0, 0, 0]))
            q = loads.get("distributed_force", [0, 0, 0])
            limit = max(force / L, 2 * weight, 2 * np.linalg.norm(q))
            for k, axis in enumerate("xyz"):
                self._add(f"distributed_force_{axis}", f"uniform load {axis}", "N/m", -limit,
                          limit, q[k])
        robot = self.spec.get("robot", {})
        act = robot.get("actuation", {})
        for i, t in enumerate(robot.get("tendons", [])):
            value = (act.get("tension") or [0] * 8)[i] if i < len(act.get("tension", [])) else 0.0
            self._add(f"tension_{i}", f"tendon {t.get('name', i)} tension", "N", 0.0,
                      max(2.0, 3 * value), value)
        for i, c in enumerate(robot.get("chambers", [])):
            pressures = act.get("chamber_pressure", [])
            value = pressures[i] if i < len(pressures) else 0.0
            self._add(f"pressure_{i}", f"chamber {c.get('name', i)} pressure", "Pa", 0.0,
                      max(2e5, 3 * value), value)
        for i, value in enumerate(act.get("jamming_pressure", [])):
            self._add(f"jamming_{i}", f"segment {i} jamming pressure", "Pa", 0.0,
                      max(1e5, 2 * value), value)
        if "pressure" in act:
            self._add("inflation", "inflation pressure", "Pa", 0.0, max(1e4, 3 * act["pressure"]),
                      act["pressure"])

    def _add(self, name, label, unit, lo, hi, value):
        self.controls.append({"name": name, "label": label, "unit": unit, "min": lo, "max": hi,
                              "value": float(value)})
        self.values[name] = float(value)

    def set_control(self, name, value):
        """Returns None, or what is wrong with the control."""
        c = next((c for c in self.controls if c["name"] == name), None)
        if c is None:
            return f"{name}: no such control (the controls are " + \
                ", ".join(c["name"] for c in self.controls) + ")"
        try:
            if isinstance(value, bool):  # JSON true would read as 1.0
                raise TypeError
            value = float(value)
        except (TypeError, ValueError):
            return f"{name}: expected a number, got {value!r}"
        if not (c["min"] <= value <= c["max"]):
            return f"{name}: {value:g} {c['unit']} is outside [{c['min']:g}, {c['max']:g}]"
        with self.lock:
            self.values[name] = value
            self.control_version += 1
        return None

    # -- stepping ---------------------------------------------------------------------------
    def _loads(self, v):
        loads = copy.deepcopy(self.spec.get("loads", {}))
        if "tip_force_x" in v:
            loads["tip_force"] = [v["tip_force_x"], v["tip_force_y"], v["tip_force_z"]]
            loads.setdefault("tip_force_frame", "world")
        if "distributed_force_x" in v:
            loads["distributed_force"] = [v[f"distributed_force_{a}"] for a in "xyz"]
        return loads

    def _actuated(self, spec, v):
        robot = spec.get("robot")
        if not robot:
            return spec
        act = robot.setdefault("actuation", {})
        act.update(_control_actuation(v, len(robot.get("tendons", [])),
                                      len(robot.get("chambers", [])),
                                      len(act.get("jamming_pressure", []))))
        # An inflated tube's pressure is its section's too: the file's rule asks both to agree.
        profile = spec["rod"].get("stiffness_profile")
        if "inflation" in v and isinstance(profile, dict) and "pressure" in profile:
            profile["pressure"] = v["inflation"]
        return spec

    def _dynamic_problem(self):
        spec = copy.deepcopy(self.spec)
        spec["analysis"] = "dynamics"
        spec.setdefault("dynamics", {}).setdefault("dt", 0.002)
        spec["dynamics"]["duration"] = max(spec["dynamics"]["dt"], 1.0)
        spec["dynamics"].pop("initial_loads", None)
        mat = spec["rod"].setdefault("material", {})
        stiff = self._stiffness()
        if "damping" not in mat and stiff:
            mat["damping"] = {"bending": VIEW_DAMPING_S * stiff[0],
                              "torsion": VIEW_DAMPING_S * stiff[1]}
            self.notes.append(f"the view adds Kelvin-Voigt damping of {VIEW_DAMPING_S} s on "
                              "bending and torsion (the file has none), so that the rod settles")
        spec["loads"] = self._loads(self.values)
        return self._actuated(spec, self.values)

    def _run(self):
        try:
            if self.mode == "dynamics":
                self._run_dynamics()
            else:
                self._run_quasi_static()
        except Exception as e:  # shown on the page; the server keeps serving
            with self.lock:
                self.state["status"] = "error"
                self.error = f"{type(e).__name__}: {e}"

    def _publish(self, rods, tip, status, t, ratio, version):
        with self.lock:
            self.state = {"frame": self.state["frame"] + 1, "status": status, "rods": rods,
                          "tip": tip, "t": t, "real_time_ratio": ratio,
                          "control_version": version}

    def _run_dynamics(self):
        problem = self.dynamic
        stepper = _core.Stepper(problem)
        # At rest in the shape the file's actuation gives, where the sliders start (a release
        # from the initial actuation would swing the robot into it as the page opens); from the
        # initial actuation when that equilibrium is out of the rest solve's reach.
        summary = stepper.initialize_at_rest(problem.loads, actuation=problem.actuation)
        if not summary.converged:
            summary = stepper.initialize_at_rest(problem.loads)
        status = "running" if summary.converged else "initial equilibrium failed"
        loads, act = copy.copy(problem.loads), copy.copy(problem.actuation)  # the controls
        n_tendons = len(self.spec.get("robot", {}).get("tendons", []))
        n_chambers = len(self.spec.get("robot", {}).get("chambers", []))
        n_jam = sum(1 for c in self.controls if c["name"].startswith("jamming_"))
        base0 = np.asarray(self.spec.get("base", {}).get("position", [0, 0, 0]), float)
        R0 = np.asarray(self.spec.get("base", {}).get("rotation", np.eye(3)), float)
        base_x = angle = 0.0
        dt = stepper.dt
        # The real-time ratio over the last two seconds of frames (wall, simulated time): a
        # window that slides, since one restarted every two seconds would, just after its
        # restart, divide a whole number of steps by a fraction of a frame.
        window = collections.deque([(time.perf_counter(), 0.0)])
        run_start_wall, run_start_sim = window[0][0], 0.0
        next_frame = run_start_wall
        while self.running:
            with self.lock:
                v = dict(self.values)
                version = self.control_version
            if "tip_force_x" in v:
                loads.tip_force = [v["tip_force_x"], v["tip_force_y"], v["tip_force_z"]]
            if "distributed_force_x" in v:
                loads.distributed_force = [v[f"distributed_force_{a}"] for a in "xyz"]
            for key, value in _control_actuation(v, n_tendons, n_chambers, n_jam).items():
                attribute = ACTUATION_ATTRIBUTE[key]
                if isinstance(value, list):  # the Actuation's arrays are longer: set their head
                    head = list(getattr(act, attribute))
                    head[:len(value)] = value
                    value = head
                setattr(act, attribute, value)
            # Real time: step until the simulated time catches up with the wall clock, at most
            # four frames' worth at once. Time lost beyond that is dropped, not made up later (a
            # slow machine runs slower than real time, and its ratio says so).
            behind = run_start_sim + time.perf_counter() - run_start_wall - stepper.time
            if behind > 4 * FRAME_S:
                run_start_wall += behind - 4 * FRAME_S
            target = stepper.time + min(4 * FRAME_S, max(0.0, behind))
            while status == "running" and stepper.time + 0.5 * dt < target:
                # The base follows its sliders at up to 1 m/s and 3 rad/s, with the twist of
                # that motion (body frame).
                vx = float(np.clip((v["base_x"] - base_x) / dt, -1.0, 1.0))
                wy = float(np.clip((v["base_angle_y"] - angle) / dt, -3.0, 3.0))
                base_x += vx * dt
                angle += wy * dt
                c, s = math.cos(angle), math.sin(angle)
                R = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]) @ R0
                twist = np.concatenate([R.T @ np.array([0, wy, 0]), R.T @ np.array([vx, 0, 0])])
                step = stepper.step(loads=loads, base_position=base0 + np.array([base_x, 0, 0]),
                                    base_rotation=R, base_twist_B=twist, actuation=act)
                if not step.converged:
                    status = f"step failed: {step.status}"
                    break
            pos = np.asarray(stepper.state()["position"]).tolist()
            sim, wall = stepper.time, time.perf_counter()
            window.append((wall, sim))
            while len(window) > 2 and wall - window[1][0] >= 2.0:
                window.popleft()
            ratio = (sim - window[0][1]) / max(wall - window[0][0], 1e-9)
            self._publish([pos], pos[-1], status, sim, ratio, version)
            next_frame += FRAME_S
            delay = next_frame - time.perf_counter()
            if delay > 0:
                time.sleep(delay)
            else:
                next_frame = time.perf_counter()

    def _run_quasi_static(self):
        solved = -1
        rods, tip, status = [], None, "solving"
        while self.running:
            with self.lock:
                v = dict(self.values)
                version = self.control_version
            if version != solved:
                spec = copy.deepcopy(self.spec)
                spec["analysis"] = "statics"
                spec.pop("dynamics", None)
                if "assembly" in spec and spec["assembly"].get("bodies"):
                    spec["assembly"]["bodies"][0]["force"] = [v["body_force_x"], v["body_force_y"],
                                                              v["body_force_z"]]
                else:
                    spec["loads"] = self._loads(v)
                spec = self._actuated(spec, v)
                try:
                    out = _core.solve(_core.parse_problem(json.dumps(spec)), False)
                    res = out["result"]
                    if "assembly" in res:
                        rods = [r["nodes"]["position"] for r in res["assembly"]["rods"]]
                    else:
                        rods = [res["nodes"]["position"]]
                    tip = rods[0][-1]
                    status = "converged" if out["converged"] else res.get("status", "failed")
                    kink = res.get("robot", {}).get("kink", {})
                    if kink.get("status", "none") != "none":  # the tube's fold, shown
                        # A torque joins the bending moment in the ratio (as the log says).
                        twisted = kink.get("torque", 0.0) > 1e-6 * kink.get("moment", 0.0)
                        name = "wrinkling ratio" if twisted else "|m|/M_w"
                        status += (f", {kink['status']} ({name} = "
                                   f"{kink.get('max_moment_ratio') or float('inf'):.3g} at "
                                   f"s = {kink['s_max']:g} m)")
                except ValueError as e:
                    status = f"refused: {e}"
                solved = version
            self._publish(rods, tip, status, 0.0, None, version)
            time.sleep(FRAME_S)

    def config(self):
        # Each control at its value now, so a reloaded page or a second tab shows what acts.
        with self.lock:
            controls = [dict(c, value=self.values.get(c["name"], c["value"]))
                        for c in self.controls]
        out = {"problem": os.path.basename(self.path), "mode": self.mode,
               "controls": controls, "notes": self.notes, "error": self.error,
               "radius": self._radius()}
        if self.error is None:
            # Dragging the tip pulls it with a spring of about the cantilever's tip stiffness,
            # 3 EI/L³ (N/m), toward the pointer.
            L, force = self._scale()
            stiff = self._stiffness()
            out["drag_stiffness"] = 3 * stiff[0] / L**3 if stiff else force / L
        return out

    def _radius(self):
        """The drawn tube's radius, m: the section's (outer) radius, else the radius of a circle
        of its area (a rectangle's w h, an explicit section's area), as the VTK output's."""
        sec = self._rod().get("section", {}) if self.error is None else {}
        if sec.get("radius") or sec.get("outer_radius"):
            return sec.get("radius") or sec.get("outer_radius")
        area = sec.get("area") or (sec.get("width", 0) * sec.get("height", 0))
        return math.sqrt(area / math.pi) if area and area > 0 else 0.005

    def snapshot(self):
        with self.lock:
            out = dict(self.state)
        out["error"] = self.error
        return out


def make_handler(live, web_dir):
    files = {"/": ("index.html", "text/html"), "/index.html": ("index.html", "text/html"),
             "/app.js": ("app.js", "text/javascript"),
             "/three.min.js": (os.path.join("node_modules", "three", "build", "three.min.js"),
                               "text/javascript")}

    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *args):  # quiet: the page shows what happens
            pass

        def _send(self, code, body, kind="application/json"):
            data = body if isinstance(body, bytes) else json.dumps(body).encode()
            self.send_response(code)
            self.send_header("Content-Type", kind)
            self.send_header("Content-Length", str(len(data)))
            self.send_header("Cache-Control", "no-store")
            self.end_headers()
            self.wfile.write(data)

        def do_GET(self):
            if self.path == "/state":
                return self._send(200, live.snapshot())
            if self.path == "/config":
                return self._send(200, live.config())
            if self.path in files:
                name, kind = files[self.path]
                try:
                    with open(os.path.join(web_dir, name), "rb") as f:
                        return self._send(200, f.read(), kind)
                except OSError:
                    return self._send(404, {"error": f"{name}: not found in {web_dir} (three.js: "
                                                     "npm ci in web/)"})
            self._send(404, {"error": f"{self.path}: not found"})

        def do_POST(self):
            if self.path != "/control":
                return self._send(404, {"error": f"{self.path}: not found"})
            try:
                length = int(self.headers.get("Content-Length", 0))
                body = json.loads(self.rfile.read(length) or b"{}")
                why = live.set_control(body.get("name"), body.get("value"))
            except (ValueError, AttributeError) as e:
                why = f"control: expected JSON {{\"name\": ..., \"value\": ...}} ({e})"
            if why:
                return self._send(400, {"error": why})
            self._send(200, {"ok": True, "control_version": live.control_version})

    return Handler


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m cosserat.view", description=__doc__.splitlines()[0])
    ap.add_argument("problem")
    ap.add_argument("--port", type=int, default=8765)
    ap.add_argument("--open", action="store_true", help="open the page in the default browser")
    args = ap.parse_args(argv)
    web = _web_dir()
    if web is None:
        raise SystemExit("cosserat view: the page's files (web/index.html) were not found next to "
                         "the package; set COSSERAT_WEB_DIR to the repository's web/ directory")
    three = os.path.join(web, "node_modules", "three", "build", "three.min.js")
    if not os.path.exists(three):
        raise SystemExit(f"cosserat view: {three} is missing: the page draws with three.js; run "
                         f"`npm ci` in {web} (scripts/test.sh does)")
    live = LiveRod(args.problem)
    try:
        server = ThreadingHTTPServer(("127.0.0.1", args.port), make_handler(live, web))
    except OSError as e:
        live.stop()
        raise SystemExit(f"cosserat view: --port {args.port}: {e.strerror} (another view or "
                         "program uses it; try another --port, or 0 for any free one)")
    url = f"http://127.0.0.1:{server.server_address[1]}/"
    print(f"cosserat view: {url} ({live.mode}{'; ' + live.error if live.error else ''})",
          flush=True)
    if args.open:
        webbrowser.open(url)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
        live.stop()


if __name__ == "__main__":
    main()
