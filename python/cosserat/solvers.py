"""The core's solver classes, taking a problem as solve() does: a Problem, a dict with the
problem-file keys, or a file path."""
from . import _core
from .results import _as_problem


class StaticSolver(_core.StaticSolver):
    __doc__ = _core.StaticSolver.__doc__

    def __init__(self, problem):
        super().__init__(_as_problem(problem))


class Stepper(_core.Stepper):
    __doc__ = _core.Stepper.__doc__

    def __init__(self, problem, dt=None, spatial_scheme=None):
        super().__init__(_as_problem(problem), dt, spatial_scheme)


class BatchStepper(_core.BatchStepper):
    __doc__ = _core.BatchStepper.__doc__

    def __init__(self, problem, count, threads=None):
        super().__init__(_as_problem(problem), count, threads)
