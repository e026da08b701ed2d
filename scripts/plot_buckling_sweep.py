#!/usr/bin/env python3
"""Plot notebooks-data/buckling_band_sweep.csv: critical load (over the uniform column's) against
the soft band's position, one curve per band factor alpha, one panel per end condition.
Usage: /usr/bin/python3 scripts/plot_buckling_sweep.py [CSV] [OUT.png]"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

src = sys.argv[1] if len(sys.argv) > 1 else "notebooks-data/buckling_band_sweep.csv"
dst = sys.argv[2] if len(sys.argv) > 2 else "out/buckling_band_sweep.png"
data = {}
with open(src) as f:
    for row in csv.DictReader(f):
        if row["critical_over_euler"] in ("", "nan", "null"):
            continue
        key = (row["boundary"], float(row["alpha"]))
        data.setdefault(key, ([], []))
        data[key][0].append(float(row["band_start"]))
        data[key][1].append(float(row["critical_over_euler"]))
ends = sorted({k[0] for k in data})
fig, axes = plt.subplots(1, len(ends), figsize=(5 * len(ends), 4), squeeze=False)
for ax, end in zip(axes[0], ends):
    for (e, alpha), (x, y) in sorted(data.items(), key=lambda kv: -kv[0][1]):
        if e == end:
            ax.plot(x, y, ".-", label=f"α = {alpha:g}")
    ax.set_title(end)
    ax.set_xlabel("band start (m)")
    ax.set_ylabel("P_cr / P_cr(uniform)")
    ax.legend(fontsize=7)
os.makedirs(os.path.dirname(dst) or ".", exist_ok=True)
fig.savefig(dst, dpi=120, bbox_inches="tight")
print("wrote", dst)
