#!/usr/bin/python3
"""`cosserat sweep` killed part-way, by SIGKILL and then SIGTERM, and run again to the end: every
point has exactly one row, and the rows (all but the timing column) are those of a run on one
thread that was never interrupted.

  kill_and_resume.py COSSERAT_BINARY STUDY.json WORK_DIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time


def rows(path):
    with open(path) as f:
        lines = f.read().splitlines()
    out = {}
    for line in lines[1:]:
        k = int(line.split(",", 1)[0])
        if k in out:
            sys.exit(f"{path}: point {k} has two rows")
        out[k] = line.rsplit(",", 1)[0]
    return lines[0], out


def main(binary, study, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    clean, resumed = os.path.join(work, "clean.csv"), os.path.join(work, "resumed.csv")
    subprocess.run([binary, "sweep", study, "--out", clean, "--threads", "1"], check=True,
                   stderr=subprocess.DEVNULL)
    header, expected = rows(clean)
    counts = []
    for sig in (signal.SIGKILL, signal.SIGTERM):
        p = subprocess.Popen([binary, "sweep", study, "--out", resumed, "--threads", "2"],
                             stderr=subprocess.DEVNULL)
        time.sleep(0.08)
        p.send_signal(sig)
        p.wait()
        counts.append(len(rows(resumed)[1]) if os.path.exists(resumed) else 0)
    subprocess.run([binary, "sweep", study, "--out", resumed, "--threads", "2"], check=True,
                   stderr=subprocess.DEVNULL)
    got_header, got = rows(resumed)
    print(f"rows after SIGKILL {counts[0]}, after SIGTERM {counts[1]}, at the end {len(got)} "
          f"of {len(expected)}")
    ok = got_header == header and got == expected
    print("identical to the uninterrupted run" if ok else "DIFFERENT from the uninterrupted run")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
