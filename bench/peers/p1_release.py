#!/usr/bin/env python3
"""P1 peer benchmark: whole-process timing of the peer release (BENCHMARKS.md, "Dynamics: the
peer release"), this library's `cosserat solve` against peer binaries, interleaved round by round.

    python3 bench/peers/p1_release.py --cosserat build/apps/cosserat \
        --peer till=/tmp/till_release [--peer NAME=BINARY ...] [--rounds 9] [--csv OUT.csv]

Each round runs, in turn: our problem with default settings (examples/cantilever_release.json,
RK4 across pairs of segments in s), the first peer, the same with RK4 on every segment
(bench/problems/peer_rk4.json), the next peer, with Heun (bench/problems/peer_heun.json), ...
(ours and theirs alternate; the order rotates by one program each round). Each run is
a whole process: start-up, the initial equilibrium, 12 500 steps, our JSON result written to
/tmp (the problems record a frame every 10 ms), the peer's output as its binary does it.
CPU time is user + sys of the child (os.wait4); wall is time.perf_counter around it.
Real-time ratio = 25 s simulated / time. Speed-ups ours/theirs are paired within a round
(same machine state) and summarised as min and median over rounds.
"""
import argparse
import csv
import os
import re
import statistics
import sys
import time

SIMULATED = 25.0
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))


def run_timed(cmd):
    """Runs cmd; returns (cpu_s, wall_s, exit_code, stdout+stderr text)."""
    r, w = os.pipe()
    t0 = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        os.close(r)
        os.dup2(w, 1)
        os.dup2(w, 2)
        try:
            os.execv(cmd[0], cmd)
        finally:
            os._exit(127)
    os.close(w)
    chunks = []
    while True:
        b = os.read(r, 65536)
        if not b:
            break
        chunks.append(b)
    os.close(r)
    _, status, ru = os.wait4(pid, 0)
    wall = time.perf_counter() - t0
    return ru.ru_utime + ru.ru_stime, wall, os.waitstatus_to_exitcode(status), b"".join(chunks).decode()


def loop_time(text):
    """The program's own timing of its time loop, if it prints one (s)."""
    m = re.search(r"Time elasped: ([0-9.eE+-]+)s", text)          # Till et al. (sic)
    if m:
        return float(m.group(1))
    m = re.search(r"simulated in ([0-9.eE+-]+) s", text)          # cosserat's summary line
    return float(m.group(1)) if m else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cosserat", required=True, help="our cosserat binary")
    ap.add_argument("--peer", action="append", default=[], metavar="NAME=BINARY",
                    help="a peer binary run without arguments (repeatable)")
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--csv", help="write every run here (round, program, cpu_s, wall_s, loop_s)")
    a = ap.parse_args()

    ours = [
        ("ours_default", [os.path.abspath(a.cosserat), "solve",
                          os.path.join(REPO, "examples/cantilever_release.json"),
                          "--out", "/tmp/p1_release_default.json"]),
        ("ours_rk4", [os.path.abspath(a.cosserat), "solve", os.path.join(REPO, "bench/problems/peer_rk4.json"),
                      "--out", "/tmp/p1_release_rk4.json"]),
        ("ours_heun", [os.path.abspath(a.cosserat), "solve", os.path.join(REPO, "bench/problems/peer_heun.json"),
                       "--out", "/tmp/p1_release_heun.json"]),
    ]
    peers = []
    for spec in a.peer:
        name, _, path = spec.partition("=")
        peers.append((name, [os.path.abspath(path)]))
    if not peers:
        sys.exit("give at least one --peer NAME=BINARY")
    # Alternate ours and theirs: rk4, peer1, heun, peer2, rk4?, ... (each program once per round).
    order = []
    oi = pi = 0
    while oi < len(ours) or pi < len(peers):
        if oi < len(ours):
            order.append(ours[oi]); oi += 1
        if pi < len(peers):
            order.append(peers[pi]); pi += 1
        elif oi >= len(ours):
            break
    names = [n for n, _ in order]

    rows = []
    for rnd in range(a.rounds):
        k = rnd % len(order)
        line = []
        for name, cmd in order[k:] + order[:k]:
            cpu, wall, code, text = run_timed(cmd)
            if code != 0:
                sys.exit(f"{name} exited with {code}:\n{text}")
            rows.append({"round": rnd, "program": name, "cpu_s": cpu, "wall_s": wall, "loop_s": loop_time(text)})
            line.append(f"{name} {cpu:.3f}/{wall:.3f}")
        print(f"round {rnd}: " + ", ".join(line) + "  (CPU/wall s)", flush=True)

    def times(name, key):
        return [r[key] for r in rows if r["program"] == name]

    def paired(num, den, key):
        a_ = {r["round"]: r[key] for r in rows if r["program"] == num}
        b_ = {r["round"]: r[key] for r in rows if r["program"] == den}
        return [b_[i] / a_[i] for i in sorted(a_)]

    print(f"\n{a.rounds} rounds. Real-time ratio = {SIMULATED:g} s / time (min over rounds = from the "
          f"slowest run, max = fastest, median)")
    print(f"{'program':<14} {'CPU s min/median':>18} {'RT ratio (CPU) min/median/max':>32} {'RT ratio (wall) min/median/max':>33} {'own loop s median':>18}  (ours: the CLI's 'simulated in', wall; Till: 'Time elasped', std::clock CPU)")
    for n in names:
        c, w, l = times(n, "cpu_s"), times(n, "wall_s"), times(n, "loop_s")
        rc = [SIMULATED / x for x in c]
        rw = [SIMULATED / x for x in w]
        print(f"{n:<14} {min(c):8.3f}/{statistics.median(c):<8.3f} "
              f"{min(rc):10.1f}/{statistics.median(rc):6.1f}/{max(rc):6.1f}x    "
              f"{min(rw):10.1f}/{statistics.median(rw):6.1f}/{max(rw):6.1f}x    "
              f"{statistics.median(l):12.3f}")
    print("\nspeed-up ours/theirs = their time / our time, paired within each round: min / median "
          "(CPU; wall); and the ratio of the fastest CPU times over all rounds")
    for o, _ in ours:
        for p, _ in peers:
            sc, sw = paired(o, p, "cpu_s"), paired(o, p, "wall_s")
            best = min(times(p, "cpu_s")) / min(times(o, "cpu_s"))
            print(f"{o} vs {p}: CPU {min(sc):.2f} / {statistics.median(sc):.2f}x;  "
                  f"wall {min(sw):.2f} / {statistics.median(sw):.2f}x;  fastest CPU runs {best:.2f}x")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            wr = csv.DictWriter(f, fieldnames=["round", "program", "cpu_s", "wall_s", "loop_s"])
            wr.writeheader()
            for r in rows:
                wr.writerow({k: (f"{v:.4f}" if isinstance(v, float) else v) for k, v in r.items()})
        print(f"\nwrote {a.csv}")


if __name__ == "__main__":
    main()
