"""cosserat.solve: any problem, given as a Problem, a dict or a path, with NumPy results."""
import errno
import io
import json
import os
import warnings

import numpy as np

from . import _core


def _path(parent, key):
    """A field's path as the error messages of the problem files write it: rod.length, a[2]."""
    if isinstance(key, int):
        return f"{parent}[{key}]"
    return f"{parent}.{key}" if parent else str(key)


def _check_json_values(value, path="", within=()):
    """Raises ValueError for a NaN or an infinity, or for a dict or list that holds itself, and
    TypeError for a value JSON cannot hold, naming the field, before the dict is written as JSON
    (which would write NaN, not JSON). `within`: the ids of the containers on the path."""
    if isinstance(value, (dict, list, tuple)):
        if id(value) in within:
            raise ValueError(f"{path or 'problem'}: holds itself (a dict or list inside itself), "
                             "which no problem file can")
        within = within + (id(value),)
    if isinstance(value, dict):
        for key, item in value.items():
            if not isinstance(key, str):
                raise TypeError(f"{path or 'problem'}: keys must be strings, got {key!r}")
            _check_json_values(item, _path(path, key), within)
    elif isinstance(value, (list, tuple)):
        for i, item in enumerate(value):
            _check_json_values(item, _path(path, i), within)
    elif isinstance(value, np.ndarray):
        _check_json_values(value.tolist(), path)
    elif isinstance(value, (bool, str, int, np.integer, np.bool_)) or value is None:
        return
    elif isinstance(value, (float, np.floating)):
        if not np.isfinite(value):
            raise ValueError(f"{path}: expected a finite number, got {value}")
    else:
        raise TypeError(f"{path}: expected a JSON value (number, string, list, dict), "
                        f"got {type(value).__name__}")


def _json_text(value, root=""):
    """A dict (a problem or a study; an actuation under `root`) as JSON text, NumPy values
    included, bad values named."""
    try:
        _check_json_values(value, root)
    except RecursionError:  # a dict nested thousands deep: named, not Python's own error
        raise ValueError(f"{root or 'problem'}: nested too deeply to be a problem's "
                         "values") from None
    return json.dumps(value, allow_nan=False,
                      default=lambda v: v.tolist() if hasattr(v, "tolist") else v.item())


class ProblemFileNotFoundError(FileNotFoundError, ValueError):
    """A problem file that is not there: a FileNotFoundError, and a ValueError as every other
    problem that cannot be read is."""


def _load_problem_file(path):
    """The validated problem of the file at `path` (a str or os.PathLike)."""
    path = os.fspath(path)
    if not os.path.exists(path):  # "[Errno 2] no such problem file: 'path'", as open() says
        raise ProblemFileNotFoundError(errno.ENOENT, "no such problem file", path)
    return _core.load_problem(path)


def _as_problem(problem):
    if isinstance(problem, _core.Problem):
        return problem
    if isinstance(problem, dict):
        return _core.parse_problem(_json_text(problem))
    if isinstance(problem, str) and problem.lstrip().startswith("{"):
        raise ValueError("problem: got JSON text, expected a file path; pass the dict "
                         "(json.loads(text)) or cosserat.parse_problem(text)")
    if isinstance(problem, (str, os.PathLike)):
        return _load_problem_file(problem)
    raise TypeError("problem: expected a cosserat.Problem, a dict with the problem-file keys "
                    f"or a file path, got {type(problem).__name__}")


def _arrays(block):
    """The lists of a result block (nodes, trajectory) as NumPy arrays; other values as they are."""
    out = {}
    for key, value in block.items():
        if isinstance(value, list) and value and not isinstance(value[0], (dict, str)):
            try:
                out[key] = np.asarray(value, dtype=float)
                continue
            except (TypeError, ValueError):
                pass
        out[key] = value
    return out


def _frames(nodes_csv):
    """The --csv table of a dynamics run as {"t": (F,), "position": (F, N, 3)}; of an assembly
    (columns t,rod,s,x,y,z) as {"t": (F,), "rods": [(F, N_i, 3) per rod]}; None for a table
    without times, or without a frame (a run whose start did not converge)."""
    header, _, body = nodes_csv.strip().partition("\n")
    if not body or not (header.startswith("t,node") or header.startswith("t,rod")):
        return None
    # NumPy's parser (C) over the text: a Python float() per value took 35 times the run.
    rows = np.loadtxt(io.StringIO(body), delimiter=",", ndmin=2)
    times = np.unique(rows[:, 0])
    if header.startswith("t,node"):
        nodes = int(rows[:, 1].max()) + 1
        frames = rows.reshape(-1, nodes, rows.shape[1])
        return {"t": frames[:, 0, 0], "position": frames[:, :, 3:6]}
    rods = []
    for rod in range(int(rows[:, 1].max()) + 1):
        mine = rows[rows[:, 1] == rod]
        rods.append(mine[:, 3:6].reshape(len(times), -1, 3))
    return {"t": times, "rods": rods}


_WARNING = "cosserat: warning: "


def solve(problem, nodes=False):
    """Runs a problem exactly as `cosserat solve` does.

    problem: a cosserat.Problem, a dict with the problem-file keys (docs/problem-format.md), or
    the path of a problem file. Bad input raises ValueError naming every bad field.
    nodes: also record every node of every frame of a dynamics run (the --csv table).

    Returns a dict:
      converged   bool
      result      the result document as a dict (its lists as Python lists)
      log         the summary line and any hints; its warnings ("cosserat: warning: ...", a
                  result to distrust: a coarse grid, numerical damping, units) are also
                  raised as RuntimeWarning
      nodes       result["nodes"] with its lists as NumPy arrays (positions N x 3, m; s, m; ...)
      trajectory  result["trajectory"] likewise (t (s), tip_position (F x 3, m), ...), if any
      envelope    dynamics: result["envelope"] likewise (tension_max, tension_min (N),
                  moment_max (N·m), one value per node)
      frames      with nodes=True in dynamics: {"t": (F,), "position": (F, N, 3)} (m, world);
                  of an assembly {"t": (F,), "rods": [(F, N_i, 3) per rod]}
      nodes_csv   with nodes=True: the --csv table as text
      contact_force, contact_total_force   with contact surfaces (N/m per node; N)
      rods        an assembly (statics, or the last frame of its dynamics): per rod, its name
                  and its nodes' s (N_i,), position (m), curvature (1/m), moment_body (N·m)
                  and force_body (N) (N_i x 3 each)
    """
    out = _core.solve(_as_problem(problem), nodes)
    for line in out["log"].splitlines():
        if line.startswith(_WARNING):
            warnings.warn(line[len(_WARNING):], RuntimeWarning, stacklevel=2)
    result = out["result"]
    if isinstance(result.get("nodes"), dict):
        out["nodes"] = _arrays(result["nodes"])
    if isinstance(result.get("trajectory"), dict):
        out["trajectory"] = _arrays(result["trajectory"])
    if isinstance(result.get("envelope"), dict):
        out["envelope"] = _arrays(result["envelope"])
    rods = result.get("assembly", {}).get("rods") if isinstance(result.get("assembly"), dict) \
        else None
    if isinstance(rods, list) and all(isinstance(r.get("nodes"), dict) for r in rods):
        out["rods"] = [dict(_arrays(r["nodes"]), name=r.get("name")) for r in rods]
    if nodes and out.get("nodes_csv"):
        frames = _frames(out["nodes_csv"])
        if frames is not None:
            out["frames"] = frames
    return out
