"""Cosserat rods for soft and continuum robots and slender structures.

The compiled core (cosserat._core) holds the problem reader, every analysis as the `cosserat`
command runs it, the static solver and the BDF2 dynamics stepper; this package adds what makes it
pleasant from Python:

  solve(problem)      a Problem, a dict with the problem-file keys, or a file path; the result
                      with its node and trajectory arrays as NumPy (see solve's help)
  plot(out)           the rod (and its tip trajectory) of a solve's output, with matplotlib
  animate(out, path)  an MP4 (ffmpeg) or GIF (Pillow) of a dynamics run's frames
  sweep(study)        a study (docs/sweeps.md) on all cores; its rows as a list of dicts
  BatchStepper        M rods stepped together on all cores, inputs and outputs as (M, ...) arrays
  StaticSolver, Stepper, BatchStepper take a problem as solve does (Problem, dict or path)

Units are SI; positions, forces and rotations are in the world frame unless a name ends in _B
(the section's body frame: x, y across the section, z along the rod). docs/python.md has the
whole module.
"""
from . import _core
from ._core import *  # noqa: F401,F403  (Problem, Loads, Actuation, Fluid, StaticSolver, Stepper, ...)
from ._core import __version__  # noqa: F401
from .plotting import animate, plot  # noqa: F401
from .results import solve  # noqa: F401  (accepts dicts and paths; adds NumPy arrays)
from .studies import sweep  # noqa: F401
from .solvers import BatchStepper, StaticSolver, Stepper  # noqa: F401  (problems as solve takes)
from .actuation import Actuation  # noqa: F401  (fitted to a solver's problem as a dict is)
from .bend_radius import minimum_bend_radius  # noqa: F401  (an eversion robot's)


def load_problem(path):
    """Reads and validates a problem file (a str or os.PathLike path); ValueError names every
    bad field, and a file that is not there raises FileNotFoundError (a ValueError too)."""
    from .results import _load_problem_file
    return _load_problem_file(path)
