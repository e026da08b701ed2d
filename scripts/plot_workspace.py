#!/usr/bin/env python3
"""Plot the reachable tip points of notebooks-data/jamming_workspace.csv (x against z, one colour
per jam pattern). Usage: /usr/bin/python3 scripts/plot_workspace.py [CSV] [OUT.png]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

src = sys.argv[1] if len(sys.argv) > 1 else "notebooks-data/jamming_workspace.csv"
dst = sys.argv[2] if len(sys.argv) > 2 else "out/jamming_workspace.png"
series = {}
with open(src) as f:
    for row in csv.DictReader(f):
        if row["status"] != "converged":
            continue
        series.setdefault(row["pattern"], ([], []))
        series[row["pattern"]][0].append(float(row["x"]))
        series[row["pattern"]][1].append(float(row["z"]))
fig, ax = plt.subplots(figsize=(6, 5))
for name, (x, z) in sorted(series.items()):
    ax.plot(x, z, ".", ms=3, label=name)
ax.set_xlabel("tip x (m)")
ax.set_ylabel("tip z (m)")
ax.set_aspect("equal")
ax.set_title("Jamming robot: tip over tendon tension, per jam pattern (J jammed, C compliant)")
ax.legend(fontsize=7, title="segments base→tip")
import os  # noqa: E402

os.makedirs(os.path.dirname(dst) or ".", exist_ok=True)
fig.savefig(dst, dpi=120, bbox_inches="tight")
print("wrote", dst)
