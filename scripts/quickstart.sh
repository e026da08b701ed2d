#!/usr/bin/env bash
# README command 1: install what is missing, build, solve the default problem, print a summary
# and write a plot to out/cantilever.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh -DBUILD_TESTING=OFF -DCOSSERAT_BUILD_BENCHMARKS=OFF -DCOSSERAT_BUILD_EXAMPLES=ON
mkdir -p out
./build/apps/cosserat solve examples/cantilever.json --out out/cantilever.json --csv out/cantilever.csv
/usr/bin/python3 scripts/plot_rod.py out/cantilever.json out/cantilever.png
echo "result: out/cantilever.json, nodes: out/cantilever.csv, plot: out/cantilever.png"
