#!/usr/bin/env bash
# `pip install --no-build-isolation .` into a fresh virtual environment that sees the system's
# site packages (Debian's numpy, setuptools, wheel), then the module's own tests with that
# environment's interpreter and no PYTHONPATH: the module they import is the installed one.
#   run.sh SOURCE_DIR CMAKE_BUILD_DIR WORK_DIR
# COSSERAT_BUILD_DIR makes setup.py reuse the test build's CMake directory instead of building
# the library a second time.
set -euo pipefail
SRC=$1 BUILD=$2 WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
/usr/bin/python3 -m venv --system-site-packages "$WORK/venv"
cd "$SRC"
COSSERAT_BUILD_DIR="$BUILD" "$WORK/venv/bin/pip" install --no-build-isolation --no-index \
  --quiet .
env -u PYTHONPATH -u COSSERAT_WEB_DIR "$WORK/venv/bin/python" - "$WORK" "$SRC" <<'PY'
import os, sys
import cosserat
from cosserat.view import _web_dir
assert cosserat.__file__.startswith(sys.argv[1]), f"imported {cosserat.__file__}, not the installed module"
print("installed module:", cosserat.__file__)
# The live view of an installed copy serves the page of the repository it was built from.
web = os.path.realpath(os.path.join(sys.argv[2], "web"))
assert _web_dir() and os.path.realpath(_web_dir()) == web, f"page at {_web_dir()}, not {web}"
PY
env -u PYTHONPATH "$WORK/venv/bin/python" tests/python/test_cosserat_module.py
