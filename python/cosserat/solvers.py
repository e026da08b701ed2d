"""The core's solver classes, taking a problem as solve() does: a Problem, a dict with the
problem-file keys, or a file path."""
import warnings

from . import _core
from .results import _as_problem


def _warn_before_stepping(problem, dt):
    """The CLI's warnings before a dynamics run (a step too coarse for the first bending mode, a
    grid too coarse for the shear wave), raised as Python warnings."""
    for line in _core._dynamics_start_warnings(problem, dt).splitlines():
        warnings.warn(line.replace("cosserat: warning: ", ""), RuntimeWarning, stacklevel=3)


class StaticSolver(_core.StaticSolver):
    __doc__ = _core.StaticSolver.__doc__

    def __init__(self, problem):
        super().__init__(_as_problem(problem))


class Stepper(_core.Stepper):
    __doc__ = _core.Stepper.__doc__

    def __init__(self, problem, dt=None, spatial_scheme=None):
        problem = _as_problem(problem)
        super().__init__(problem, dt, spatial_scheme)
        _warn_before_stepping(problem, dt)


class BatchStepper(_core.BatchStepper):
    __doc__ = _core.BatchStepper.__doc__

    def __init__(self, problem, count, threads=None):
        problem = _as_problem(problem)
        super().__init__(problem, count, threads)
        _warn_before_stepping(problem, None)
