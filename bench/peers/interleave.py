"""What the peer tables share: timing a command, running PyElastica's cantilever, repeating a cosserat run, the median of repeated timings, and running
several generators of table rows (one per code or configuration family) in turn, so that every
code sees the same minutes of machine load, writing the CSV after each row."""
import csv
import json
import os
import resource
import subprocess
import sys


def timed(cmd):
    """Runs cmd under /usr/bin/time. Returns (exit code, stdout, stderr without the timing line,
    CPU seconds (user + sys) from /usr/bin/time (10 ms resolution), CPU seconds from the
    children's rusage (µs resolution), wall seconds)."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(["/usr/bin/time", "-f", "PEERTIME %U %S %e"] + cmd,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu_rusage = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    cpu = wall = None
    err = []
    for line in p.stderr.splitlines():
        if line.startswith("PEERTIME "):
            u, s, e = line.split()[1:]
            cpu, wall = float(u) + float(s), float(e)
        else:
            err.append(line)
    return p.returncode, p.stdout, "\n".join(err), cpu, cpu_rusage, wall


PYELASTICA_CANTILEVER = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                     "pyelastica_cantilever.py")


def run_pyelastica(elastica, elements, dt, duration, out_csv, *options):
    """Runs pyelastica_cantilever.py (P2 in PyElastica) under timed(). Returns (its JSON report,
    CPU seconds from /usr/bin/time, CPU seconds from rusage, wall seconds); exits when the run
    prints no report. `options`: further arguments (--damping, --output-interval, ...)."""
    _, out, err, cpu, cpu_rusage, wall = timed([
        "/usr/bin/python3", PYELASTICA_CANTILEVER, "--elastica", elastica,
        "--elements", str(elements), "--dt", repr(dt), "--duration", repr(duration),
        "--out", out_csv, *options])
    try:
        report = json.loads(out.strip().splitlines()[-1])
    except (ValueError, IndexError):
        sys.exit("pyelastica run failed:\n" + err)
    return report, cpu, cpu_rusage, wall


def repeat_solve(cosserat, problem, out_json, out_csv, repeat):
    """Runs `cosserat solve problem --out out_json --csv out_csv` up to `repeat` times, stopping
    after a run that does not converge, and yields None between runs so that the other codes take
    their turn (use it with `yield from`). Returns (the last result document, CPU seconds from
    /usr/bin/time, CPU seconds from rusage, wall seconds), one per run. Exits on a refused
    problem."""
    result, cpus, cpus_rusage, walls = {}, [], [], []
    for rep in range(repeat):
        code, _, err, cpu, cpu_rusage, wall = timed(
            [cosserat, "solve", problem, "--out", out_json, "--csv", out_csv])
        if code == 2:
            sys.exit("cosserat refused %s:\n%s" % (problem, err))
        with open(out_json) as f:
            result = json.load(f)
        cpus.append(cpu)
        cpus_rusage.append(cpu_rusage)
        walls.append(wall)
        if result["status"] != "converged":
            break
        if rep + 1 < repeat:
            yield None
    return result, cpus, cpus_rusage, walls


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
