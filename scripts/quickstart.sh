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
# The Python module, importable without PYTHONPATH: a .pth file in Debian's site directory
# points at build/python (pip install --no-build-isolation . installs a copy instead;
# docs/python.md).
site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
if mkdir -p "$site" 2>/dev/null && echo "$PWD/build/python" > "$site/cosserat-build.pth" 2>/dev/null &&
   (cd / && /usr/bin/python3 -c 'import cosserat' 2>/dev/null); then
  echo "python: import cosserat works (via $site/cosserat-build.pth)"
else
  echo "python: run with PYTHONPATH=$PWD/build/python to import cosserat"
fi
echo "result: out/cantilever.json, nodes: out/cantilever.csv, plot: out/cantilever.png"
