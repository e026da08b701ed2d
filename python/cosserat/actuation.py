"""cosserat.Actuation: what the actuators do, remembering which fields were given, so that a
solver fits it to its problem as it fits a dict with the file's robot.actuation keys."""
import copy

import numpy as np

from . import _core
from ._numbers import refuse_bools

# The list fields, each with the problem's count of what it acts on, its noun and where the
# file lists those.
_LISTS = {"tendon_tension": ("tendon_count", "tendon", "robot.tendons"),
          "chamber_pressure": ("chamber_count", "chamber", "robot.chambers"),
          "jamming_pressure": ("jamming_segment_count", "segment",
                               "rod.stiffness_profile.segments")}
_FIELDS = ("pressure",) + tuple(_LISTS)


def _list_field(name):
    """A list field as the core's view, recorded as given when set (with its length); a view
    taken before is remembered with its values, so that an edit in place through it counts as
    given (its length then unknown) and a mere read does not."""
    core = getattr(_core.Actuation, name)

    def get(self):
        view = core.__get__(self)
        viewed = self.__dict__["_viewed"]
        if name not in self.__dict__["_given"] and name not in viewed:
            viewed[name] = view.copy()
        return view

    def set_(self, value):
        refuse_bools(value, f"actuation.{name}")
        core.__set__(self, value)
        self.__dict__["_given"][name] = len(value)

    return property(get, set_, doc=core.__doc__)


class Actuation(_core.Actuation):
    """What the actuators do: tendon_tension (N, in the robot's tendon order), chamber_pressure
    (Pa, gauge, in the robot's chamber order), pressure (Pa, inflation) and jamming_pressure (Pa,
    per switchable segment). Fields may be given as keywords: Actuation(tendon_tension=[1, 0, 0]).

    Handed to a solver it follows the problem file's rules, as a dict does: a list set has one
    value per tendon, chamber or segment; the pressures the rod's section reads (inflation and
    jamming pressures), neither set nor edited through their arrays, stay the problem's (in the
    copy the solver takes: this object is not changed). The arrays are views: writing
    act.tendon_tension[0] = 2 sets the tension."""

    tendon_tension = _list_field("tendon_tension")
    chamber_pressure = _list_field("chamber_pressure")
    jamming_pressure = _list_field("jamming_pressure")

    def __init__(self, **fields):
        super().__init__()
        self.__dict__["_given"] = {}
        self.__dict__["_viewed"] = {}  # list fields read, not set: their values then
        for name, value in fields.items():
            setattr(self, name, value)

    def __setattr__(self, name, value):
        if name not in _FIELDS:
            raise AttributeError(f"Actuation has no field {name!r} (fields: "
                                 f"{', '.join(_FIELDS)})")
        refuse_bools(value, f"actuation.{name}")
        super().__setattr__(name, value)
        if name == "pressure":
            self.__dict__["_given"]["pressure"] = None

    def given(self):
        """The fields given: {name: the list's length, or None (pressure, or a list edited in
        place through its view)}."""
        given = dict(self.__dict__["_given"])
        for name, then in self.__dict__["_viewed"].items():
            if name not in given and not np.array_equal(_core_list(self, name), then,
                                                         equal_nan=True):
                given[name] = None
        return given

    def __repr__(self):
        # A list at the length it was given, trailing zeros too, else up to its last non-zero
        # value.
        given = self.given()
        parts = []
        for name in _LISTS:
            values = list(_core_list(self, name))
            used = max((i + 1 for i, v in enumerate(values) if v != 0), default=0)
            shown = values[:max(given.get(name) or 0, used)]
            parts.append(f"{name}=[{', '.join(f'{v:.6g}' for v in shown)}]")
        return f"Actuation({', '.join(parts)}, pressure={self.pressure:.6g})"

    def __copy__(self):  # the core's own copy would drop what was given
        return _rebuild(*self.__reduce__()[1])

    def __deepcopy__(self, memo):
        return self.__copy__()

    def __reduce__(self):
        given = self.given()
        return (_rebuild, ({name: list(_core_list(self, name))
                            if name in _LISTS else self.pressure for name in _FIELDS},
                           dict(given)))


def _core_list(actuation, name):
    """A list field's values, read past the record of what was given."""
    return getattr(_core.Actuation, name).__get__(actuation)


def _rebuild(values, given):
    """An Actuation from __reduce__: its values, and which of them were given."""
    a = Actuation()
    for name, value in values.items():
        (getattr(_core.Actuation, name).__set__ if name in _LISTS else
         _core.Actuation.pressure.__set__)(a, value)
    a.__dict__["_given"] = dict(given)
    a.__dict__["_viewed"] = {}
    return a


class ProblemRules:
    """What fitting an Actuation needs of a problem, read once (a solver's step is a hot path):
    the counts its lists act on, and the section's pressures in its file."""

    def __init__(self, problem):
        self.counts = {field: getattr(problem, count_name)
                       for field, (count_name, _, _) in _LISTS.items()}
        self.file = copy.copy(problem.actuation)  # a whole state, as the solver took it
        self.has_pressure = self.file.pressure != 0
        self.has_jamming = bool(any(self.file.jamming_pressure))
        # Whether the section reads an inflation pressure, asked of the file's rules once: their
        # refusal of one (a chambered finger's pressures are chamber_pressure) is kept to say.
        try:
            _core._parse_actuation(problem, '{"pressure": 1.0}')
            self.pressure_refused = None
        except ValueError as e:
            self.pressure_refused = str(e)


def fit_to_problem(actuation, rules):
    """An Actuation made in Python, fitted to a problem (its ProblemRules) as a dict with the
    file's keys is: a list set with another count than what it acts on is refused with a
    ValueError naming the field; the section's pressures never given take the problem's, in a
    copy (the object is left as it is). Others (a Stepper's or a Problem's, which hold a whole
    state) pass as they are."""
    if not isinstance(actuation, Actuation):
        return actuation
    given = actuation.given()
    for field, (_, noun, source) in _LISTS.items():
        length, count = given.get(field), rules.counts[field]
        # With none to act on, the core's check names the value that would act on nothing. A
        # whole array read back from an Actuation (its capacity, zeros past the count) stands
        # for its first `count` values.
        values = _core_list(actuation, field)
        read_back = length == len(values) and not any(values[count:])
        if length is not None and count > 0 and length != count and not read_back:
            raise ValueError(f"actuation.{field}: expected one value per {noun} "
                             f"({count} in {source}), got {length}")
    if "pressure" in given and actuation.pressure != 0 and rules.pressure_refused:
        raise ValueError(rules.pressure_refused.replace("got 1.0", f"got {actuation.pressure}"))
    keep_pressure = rules.has_pressure and "pressure" not in given
    keep_jamming = rules.has_jamming and "jamming_pressure" not in given
    if not (keep_pressure or keep_jamming):
        return actuation
    fitted = _core.Actuation()
    for name in _FIELDS:
        source = rules.file if (name == "pressure" and keep_pressure) or (
            name == "jamming_pressure" and keep_jamming) else actuation
        value = _core_list(source, name) if name in _LISTS else source.pressure
        getattr(_core.Actuation, name).__set__(fitted, value)
    return fitted
