"""cosserat.Actuation: what the actuators do, remembering which fields were set, so that a
solver fits it to its problem as it fits a dict with the file's robot.actuation keys."""
from . import _core

# The list fields, each with the problem's count of what it acts on and the file key it
# answers to.
_LISTS = {"tendon_tension": ("tendon_count", "tendons", "robot.tendons"),
          "chamber_pressure": ("chamber_count", "chambers", "robot.chambers"),
          "jamming_pressure": ("jamming_segment_count", "segments",
                               "rod.stiffness_profile.segments")}


class Actuation(_core.Actuation):
    """What the actuators do: tendon_tension (N, in the robot's tendon order), chamber_pressure
    (Pa, gauge, in the robot's chamber order), pressure (Pa, inflation) and jamming_pressure (Pa,
    per switchable segment). Fields may be given as keywords: Actuation(tendon_tension=[1, 0, 0]).

    Handed to a solver it follows the problem file's rules, as a dict does: a list set has one
    value per tendon, chamber or segment; the pressures the rod's section reads (its inflation
    and jamming pressures), never set, stay the problem's. The arrays are views: writing
    act.tendon_tension[0] = 2 sets the tension."""

    def __init__(self, **fields):
        super().__init__()
        self.__dict__["_given"] = {}
        for name, value in fields.items():
            if not hasattr(_core.Actuation, name):
                raise TypeError(f"Actuation: unknown field {name!r} (fields: pressure, "
                                f"{', '.join(_LISTS)})")
            setattr(self, name, value)

    def __setattr__(self, name, value):
        super().__setattr__(name, value)
        given = self.__dict__.setdefault("_given", {})
        given[name] = len(value) if name in _LISTS else None
        self.__dict__["_fitted_to"] = None  # to be fitted again


def fit_to_problem(actuation, problem):
    """An Actuation made in Python fitted to `problem` the first time it meets it (and again
    after a field is set): a list shorter than what it acts on is refused with a ValueError
    naming the field; the section's pressures never set take the problem's. Others (a Stepper's
    or a Problem's copies, which hold a whole state) pass as they are."""
    if not isinstance(actuation, Actuation) or actuation.__dict__.get("_fitted_to") is problem:
        return actuation
    given = actuation.__dict__.get("_given", {})
    for field, (count_name, noun, source) in _LISTS.items():
        if field in given:
            count = getattr(problem, count_name)
            if given[field] < count:
                raise ValueError(f"actuation.{field}: expected one value per {noun[:-1]} "
                                 f"({count} in {source}), got {given[field]}")
    file_actuation = problem.actuation
    if "pressure" not in given:
        _core.Actuation.pressure.__set__(actuation, file_actuation.pressure)
    if "jamming_pressure" not in given:
        _core.Actuation.jamming_pressure.__set__(actuation, file_actuation.jamming_pressure)
    actuation.__dict__["_fitted_to"] = problem
    return actuation
