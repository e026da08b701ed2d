"""The minimum bend radius of an eversion (vine) robot, from Python as examples/eversion_bend_radius
runs it in C++ (docs/eversion.md, "Minimum bend radius")."""
import warnings

from . import _core
from .results import _as_problem
from .solvers import _set_keyed_loads

# The load pattern's keys (a problem file's loads keys that a pattern may grow).
_PATTERN_KEYS = ("distributed_force", "tip_force", "tip_moment", "tip_force_frame",
                 "tip_moment_frame")


def minimum_bend_radius(problem, pattern, length=None, bands=True, angle=None, steps=20):
    """The smallest radius of curvature (m) the robot's body reaches as the load `pattern` (a
    cosserat.Loads or a dict with the file's loads keys: a steering tip_moment, a lateral
    tip_force, ...) grows from 0 to 1 on top of the problem's loads, at the everted `length` (m;
    default rod.length) and the problem's pressure: up to the kink (the bending moment reaches
    the wrinkling moment N r / 2 of the wall's axial force N, pi p r^3 / 2 under inflation
    alone; limit "kink"), the whole pattern ("actuation") or a failed
    solve ("no_convergence"); "kinked_by_fixed_loads" when the problem's loads alone kink the
    tube at this length (no bend radius then: a RuntimeWarning says so). With `angle` (rad, in
    (0, pi)) instead: the radius when the tip has turned by that angle from the base direction
    (limit "angle"; a RuntimeWarning when the tube kinks before it turns that far). bands=False
    takes the tube without its constrictions. Returns a dict: min_radius (m), s (m, where),
    load_factor, limit, kink_ratio (the largest bending moment over the wrinkling moment),
    solves."""
    problem = _as_problem(problem)
    if isinstance(pattern, dict):
        loads = _core.Loads()
        _set_keyed_loads(loads, pattern, _PATTERN_KEYS, "pattern",
                         f"a pattern grows {', '.join(_PATTERN_KEYS)}; the problem's loads stay")
        pattern = loads
    out = _core._minimum_bend_radius(problem, pattern, length, bands, angle, steps)
    if out["limit"] == "kinked_by_fixed_loads":
        warnings.warn(f"the problem's loads alone kink the tube at this length (kink_ratio "
                      f"{out['kink_ratio']:.3g}): its radius is that of a folded tube, not a "
                      f"bend radius; try a shorter length or a higher pressure",
                      RuntimeWarning, stacklevel=2)
    elif out["limit"] == "angle" and out["kink_ratio"] >= 1.0:
        warnings.warn(f"the tube kinks before its tip turns by this angle (kink_ratio "
                      f"{out['kink_ratio']:.3g} at the angle): the radius is past the kink",
                      RuntimeWarning, stacklevel=2)
    return out
