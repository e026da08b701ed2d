"""The core's solver classes, taking a problem as solve() does: a Problem, a dict with the
problem-file keys, or a file path."""
import copy
import warnings

import numpy as np

from . import _core
from ._numbers import refuse_bools
from .actuation import ProblemRules, fit_to_problem
from .results import _as_problem, _json_text


def _warn_before_stepping(problem, dt):
    """The CLI's warnings before a dynamics run (a step too coarse for the first bending mode, a
    grid too coarse for the shear wave), raised as Python warnings."""
    for line in _core._dynamics_start_warnings(problem, dt).splitlines():
        warnings.warn(line.replace("cosserat: warning: ", ""), RuntimeWarning, stacklevel=3)


class StaticSolver(_core.StaticSolver):
    __doc__ = _core.StaticSolver.__doc__

    def __init__(self, problem):
        problem = copy.copy(_as_problem(problem))  # the solver's own, as the core's copy is
        super().__init__(problem)
        self._problem = problem  # its environment and actuation rules, for dict inputs
        self._rules = ProblemRules(problem)

    def solve(self, loads=None, base_position=None, base_rotation=None, actuation=None):
        refuse_bools(base_position, "base_position")
        refuse_bools(base_rotation, "base_rotation")
        summary = super().solve(_loads_from(loads, self._problem), base_position, base_rotation,
                                _actuation_from(actuation, self._problem, self._rules))
        if summary.converged and summary.stability_index > 0:
            head = (f"the equilibrium is unstable ({summary.stability_index} unstable "
                    "direction(s)): ")
            if self._problem.contact_count > 0:  # as the command says it: no settling there
                why = ("on the frictionless contact surfaces of statics the rod can slide off "
                       "them, or the loads are past a critical point; dynamics with friction "
                       "on the surfaces holds it")
            else:  # cosserat.solve() and the command settle beside it; this solver stays
                why = ("the loads are past a critical point on the branch this solver "
                       "follows; cosserat.solve() settles beside it, or ramp the loads with a "
                       "small side load to follow the stable branch")
            warnings.warn(head + why, RuntimeWarning, stacklevel=2)
        return summary

    def __repr__(self):
        return (f"StaticSolver(boundary={self._problem.boundary}, length={self._problem.length:g}"
                f" m, nodes={self._problem.nodes}, pieces={self.pieces})")

    solve.__doc__ = (_core.StaticSolver.solve.__doc__ or "") + (
        " loads and actuation may also be dicts with the problem file's keys. An unstable "
        "equilibrium (summary.stability_index > 0) is returned as solved, with a "
        "RuntimeWarning: this solver does not settle beside it as cosserat.solve() does.")


# The problem file's `loads` keys a step takes, at their defaults.
_LOAD_DEFAULTS = {"gravity": [0, 0, 0], "distributed_force": [0, 0, 0], "tip_force": [0, 0, 0],
                  "tip_moment": [0, 0, 0], "tip_force_frame": "world",
                  "tip_moment_frame": "world"}


def _set_keyed_loads(loads, value, keys, where, allowed):
    """Sets on `loads` the entries of the dict `value` (a problem file's loads keys among `keys`),
    each named `where.key` when refused: an unknown key (with `allowed`, what is taken) or a
    value of the wrong kind."""
    for key, entry in value.items():
        if key not in keys:
            raise ValueError(f"{where}.{key}: unknown key ({allowed})")
        refuse_bools(entry, f"{where}.{key}")
        try:
            setattr(loads, key, entry)
        except (TypeError, ValueError):  # the binding names the field, not where it sits
            expected = ('"world" or "body"' if key.endswith("_frame")
                        else "an array of 3 numbers")
            raise ValueError(f"{where}.{key}: expected {expected}, got {entry!r}") from None


def _loads_from(value, holder):
    """A Loads from a dict with the problem file's `loads` keys (absent ones at their defaults,
    as in a file) in the environment of holder.loads (a Stepper's or a Problem's: of a copy, the
    fluid, contact and bit friction stay); a Loads or None as given, without that copy (step()
    is a hot path)."""
    if not isinstance(value, dict):
        if value is not None and not isinstance(value, _core.Loads):
            raise TypeError(f"loads: expected a cosserat.Loads or a dict with the problem "
                            f"file's loads keys, got {type(value).__name__}")
        # The same slip as a dict without "gravity": cosserat.Loads() starts with none. (The
        # Loads' own gravity first: a step is a hot path.)
        if value is not None and not np.any(value.gravity):
            filed = getattr(holder, "_problem", holder).loads.gravity  # the problem's, m/s²
            if np.any(filed):
                warnings.warn(f"loads: this Loads has no gravity (the problem's is "
                              f"{np.array(filed).tolist()} m/s²); start from .loads and change "
                              "what differs", RuntimeWarning, stacklevel=3)
        return value
    loads = copy.copy(holder.loads)  # its fluid, contact and bit stay; the keyed loads start over
    gravity = np.array(loads.gravity)  # m/s², the holder's
    for key, default in _LOAD_DEFAULTS.items():
        setattr(loads, key, default)
    _set_keyed_loads(loads, value, _LOAD_DEFAULTS, "loads",
                     f"a step's loads take {', '.join(_LOAD_DEFAULTS)}; the environment stays "
                     "the problem's")
    if "gravity" not in value and np.any(gravity):
        # As in a file, a load left out is not there; gravity left out of a step's loads is the
        # one a controller most likely meant to keep (a rod that no longer sags).
        warnings.warn(f"loads: the dict has no \"gravity\", so these loads have none (the "
                      f"{type(holder).__name__}'s is {gravity.tolist()} m/s²); give it, or "
                      "start from .loads and change what differs", RuntimeWarning,
                      stacklevel=3)
    return loads


def _actuation_from(value, problem, rules):
    """An Actuation from a dict with the keys of the problem file's robot.actuation (tension,
    chamber_pressure, jamming_pressure, pressure), checked by the file's rules for `problem` (one
    value per tendon, chamber or jamming segment); a cosserat.Actuation fitted to the problem by
    the same rules (actuation.fit_to_problem, with the problem's `rules` read once); another
    Actuation or None as given."""
    if not isinstance(value, dict):
        return fit_to_problem(value, rules)
    if "length" in value:  # the file's key, for an inverse solve these solvers do not run
        raise ValueError("actuation.length: tendon lengths are met by an inverse solve, which "
                         "cosserat.solve() runs on a statics problem (robot.actuation = "
                         "{\"length\": [...]}); this solver takes tensions")
    return _core._parse_actuation(problem, _json_text(value, "actuation"))


class Stepper(_core.Stepper):
    __doc__ = _core.Stepper.__doc__

    def __init__(self, problem, dt=None, spatial_scheme=None):
        refuse_bools(dt, "dt")
        problem = copy.copy(_as_problem(problem))  # the stepper's own, as the core's copy is
        super().__init__(problem, dt, spatial_scheme)
        self._problem = problem  # the rules a dict actuation is checked by
        self._rules = ProblemRules(problem)
        # Until a base_twist_B is given or the warning below is out: the clamp's last pose (a
        # column's clamp does not move: step() refuses a base pose or twist).
        self._clamp = None if problem.boundary in ("clamped-clamped", "clamped-pinned") else [
            np.asarray(problem.base_position), np.asarray(problem.base_rotation)]
        _warn_before_stepping(problem, dt)

    def __repr__(self):
        try:
            time = f"{self.time:g} s"
        except RuntimeError:  # a reset that did not converge leaves no state
            time = "no state"
        return (f"Stepper(boundary={self._problem.boundary}, length={self._problem.length:g} m, "
                f"nodes={self._problem.nodes}, dt={self.dt:g} s, time={time})")

    def initialize_at_rest(self, loads=None, actuation=None):
        return super().initialize_at_rest(_loads_from(loads, self),
                                          _actuation_from(actuation, self._problem, self._rules))

    def step(self, loads=None, base_position=None, base_rotation=None, base_twist_B=None,
             base_wrench_B=None, actuation=None):
        if not (base_position is None and base_rotation is None and base_twist_B is None
                and base_wrench_B is None):  # a base moved (step() is a hot path)
            for name, value in (("base_position", base_position),
                                ("base_rotation", base_rotation), ("base_twist_B", base_twist_B),
                                ("base_wrench_B", base_wrench_B)):
                refuse_bools(value, name)
        if base_wrench_B is not None and self._problem.boundary != "free-free":
            raise ValueError("base_wrench_B: acts on a free-free rod's s = 0 end; this rod's "
                             f"base is {self._problem.boundary} (its clamp takes any wrench)")
        summary = super().step(_loads_from(loads, self), base_position, base_rotation,
                               base_twist_B, base_wrench_B,
                               _actuation_from(actuation, self._problem, self._rules))
        # Said of a step the core took: a refused call applies nothing, the warning included.
        if self._clamp is not None:
            self._check_clamp_twist(base_position, base_rotation, base_twist_B)
        return summary

    @property
    def actuation(self):
        """The actuation the next step() applies unless given another: edited in place or
        assigned (an Actuation or a dict, fitted to the problem as step() fits one), it takes
        effect there; initialize_at_rest() resets it to the problem's."""
        return _core.Stepper.actuation.fget(self)

    @actuation.setter
    def actuation(self, value):
        _core.Stepper.actuation.fset(self, _actuation_from(value, self._problem, self._rules))

    @property
    def loads(self):
        """The loads the next step() applies unless given others: assigned (a Loads or a dict
        with the problem file's loads keys, read as step() reads one; checked then) or edited in
        place (checked at that step), they are its; initialize_at_rest() resets them to the
        problem's."""
        return _core.Stepper.loads.fget(self)

    @loads.setter
    def loads(self, value):
        if value is None:
            raise TypeError("loads: expected a cosserat.Loads or a dict with the problem file's "
                            "loads keys, got None")
        _core.Stepper.loads.fset(self, _loads_from(value, self))

    def _check_clamp_twist(self, base_position, base_rotation, base_twist_B):
        """A clamp moved with no base_twist_B ever given: the step takes the twist as an input
        (zero), not from the change of pose, so the rod is dragged, not carried. Warned once."""
        if base_twist_B is not None:
            self._clamp = None
            return
        for k, given in enumerate((base_position, base_rotation)):
            if given is None or np.array_equal(given, self._clamp[k]):
                continue
            self._clamp = None
            warnings.warn("base_position/base_rotation move the clamp but no base_twist_B was "
                          "given: the step takes the base's twist as an input (zero here), not "
                          "from the change of pose; pass the clamp's [angular; linear] velocity "
                          "in its own frame as base_twist_B", RuntimeWarning, stacklevel=3)
            return

    initialize_at_rest.__doc__ = (_core.Stepper.initialize_at_rest.__doc__ or "") + (
        " loads and actuation may also be dicts with the problem file's keys.")
    step.__doc__ = (_core.Stepper.step.__doc__ or "") + (
        " loads and actuation may also be dicts with the problem file's keys.")


class BatchStepper(_core.BatchStepper):
    __doc__ = _core.BatchStepper.__doc__

    def __init__(self, problem, count, threads=None):
        problem = _as_problem(problem)
        super().__init__(problem, count, threads)
        _warn_before_stepping(problem, None)

    def step(self, tip_force=None, tension=None):
        # The core reads a 1-D array as a column, (3,) as (3, 1): its shape is named as given.
        for name, value, columns in (("tip_force", tip_force, "3"), ("tension", tension,
                                                                     "tendons")):
            refuse_bools(value, name)
            if value is not None and np.ndim(value) != 2:
                raise ValueError(f"{name}: expected shape ({self.count}, {columns}), one row "
                                 f"per rod, got shape {np.shape(value)}")
        return super().step(tip_force, tension)

    step.__doc__ = _core.BatchStepper.step.__doc__


def _fitting_setter(core_property, name):
    """A Problem's `name` property whose setter fits what it is given to the problem as a solver
    fits a step's actuation: a dict with the file's keys, or a cosserat.Actuation whose section
    pressures (inflation, jamming) not given stay the problem's."""
    def set_fitted(problem, value):
        if isinstance(value, dict):
            value = _core._parse_actuation(problem, _json_text(value, name))
        else:
            value = fit_to_problem(value, ProblemRules(problem))
        core_property.__set__(problem, value)
    return property(core_property.fget, set_fitted, doc=core_property.__doc__)


_core.Problem.actuation = _fitting_setter(_core.Problem.actuation, "actuation")
_core.Problem.initial_actuation = _fitting_setter(_core.Problem.initial_actuation,
                                                  "initial_actuation")
