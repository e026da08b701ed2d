"""Numbers given in Python as a problem file's numbers are read: a bool is refused (a file's
`true` is no number either), naming where it stands."""
import numpy as np


def refuse_bools(value, where):
    """Raises ValueError naming `where` (and the index) when `value`, a number or a nested list,
    tuple or array of them, holds a bool."""
    if value is None:  # an argument not given (step() is a hot path)
        return
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{where}: expected a number, got {value!r}")
    if isinstance(value, np.ndarray):
        if value.dtype == np.bool_:
            raise ValueError(f"{where}: expected numbers, got an array of bools")
    elif isinstance(value, (list, tuple)):
        for i, entry in enumerate(value):
            refuse_bools(entry, f"{where}[{i}]")
