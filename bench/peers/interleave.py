"""What the peer tables share: the median of repeated timings, and running several generators of
table rows (one per code or configuration family) in turn, so that every code sees the same
minutes of machine load, writing the CSV after each row."""
import csv
import json


def median(v):
    v = sorted(v)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def run_interleaved(generators, rows, out_path, fields):
    """Takes one row from each generator in turn until all are done (a None row is skipped),
    appending to `rows`, printing each as JSON and rewriting `out_path` with `fields`."""
    generators = list(generators)
    while generators:
        for g in list(generators):
            try:
                row = next(g)
            except StopIteration:
                generators.remove(g)
                continue
            if row is None:
                continue
            rows.append(row)
            print(json.dumps(row), flush=True)
            with open(out_path, "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=fields)
                w.writeheader()
                for r in rows:
                    w.writerow(r)
