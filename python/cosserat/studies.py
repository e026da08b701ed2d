"""cosserat.sweep: a study (docs/sweeps.md) from Python, with its rows as a list of dicts."""
import csv
import json
import os
import tempfile
import warnings

import numpy as np

from . import _core
from .results import _json_text


def _cell(text):
    """A CSV cell as Python: empty → None, a number → float ("nan" for a result's null), an array
    of numbers the study wrote as JSON (an output pointer naming a list, "/tip/position") → a
    NumPy array, another JSON list ("/warnings") → a list, else the text."""
    if text == "":
        return None
    try:
        return float(text)
    except ValueError:
        pass
    if text.startswith("["):
        try:
            value = json.loads(text)
        except ValueError:
            return text
        if not value:
            return []
        try:
            return np.asarray(value, dtype=float)
        except (ValueError, TypeError):
            return value
    return text


def sweep(study, out=None, threads=None):
    """Runs a study: a dict with the study-file keys (a relative "problem" path is read from the
    current directory) or the path of a study file.

    out: the CSV file the rows go to, one per point as it finishes; given an existing file of the
    same study, it resumes (only the points without a row run). Default: a temporary file,
    removed once its rows are read ("csv" is then None).
    threads: default all cores.

    Returns {"rows": [one dict per point, in point order: index, each parameter by its path,
    each output by its name (a number, or a NumPy array for an output naming a list, as
    /tip/position), status, wall_time_s], "summary": {points, resumed, ran, failed, dropped,
    complete, wall_time_s, empty_outputs}, "csv": the file's path (None for the temporary one)}.
    dropped counts the lines of a resumed file that were no rows of this study.
    empty_outputs lists the outputs blank in every converged row (a pointer that names nothing
    in the result, e.g. a typo), which also raise a warning. Bad study files raise ValueError
    naming the field.
    """
    if isinstance(study, dict):
        text, base = _json_text(study), os.getcwd()
    elif isinstance(study, (str, os.PathLike)):
        try:
            with open(os.fspath(study)) as f:
                text = f.read()
        except OSError as e:
            raise ValueError(f"study: cannot read {os.fspath(study)!r} ({e.strerror})") from e
        base = os.path.dirname(os.path.abspath(os.fspath(study)))
    else:
        raise TypeError("study: expected a dict with the study-file keys or a file path, got "
                        f"{type(study).__name__}")
    if threads is not None and (isinstance(threads, bool)
                                or not isinstance(threads, (int, np.integer)) or threads < 1):
        raise ValueError(f"threads: expected a whole number >= 1, got {threads!r}")
    threads = None if threads is None else int(threads)
    temporary = out is None
    if temporary:
        handle, out = tempfile.mkstemp(prefix="cosserat_sweep_", suffix=".csv")
        os.close(handle)
        os.remove(out)
    try:
        summary = _core.sweep(text, base, os.fspath(out), threads or os.cpu_count() or 1)
        with open(out, newline="") as f:
            rows = [{k: (int(v) if k == "index" else _cell(v)) for k, v in row.items()}
                    for row in csv.DictReader(f)]
    finally:
        if temporary:
            # The rows, their partial file and the records kept beside them for a resume.
            for leftover in (out, *(os.fspath(out) + end
                                    for end in (".tmp", ".lock", ".problem.json",
                                                ".outputs.json"))):
                if os.path.exists(leftover):
                    os.remove(leftover)
    if summary["dropped"]:
        warnings.warn(f"{summary['dropped']} lines of {out} held no row of this study and were "
                      "dropped on resume", stacklevel=2)
    for output in summary["empty_outputs"]:
        warnings.warn(f"output {output} is empty in every converged point: does the pointer name "
                      "a field of the result?", stacklevel=2)
    return {"rows": rows, "summary": summary, "csv": None if temporary else os.fspath(out)}
