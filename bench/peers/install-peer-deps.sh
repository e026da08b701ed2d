#!/usr/bin/env bash
# Installs, from Debian, what the PyElastica peer (bench/peers/README.md) imports:
# numpy, numba, scipy, tqdm, typing_extensions (and matplotlib for plots). Run as root.
# The drivers then run with Debian's interpreter, /usr/bin/python3, and
# PYTHONPATH (or --elastica) pointing at the PyElastica source tree. No pip.
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then echo "install-peer-deps.sh: run as root" >&2; exit 1; fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends \
  python3 python3-numpy python3-numba python3-scipy python3-tqdm \
  python3-typing-extensions python3-matplotlib time
/usr/bin/python3 -c 'import numpy, numba, scipy, tqdm, typing_extensions; print("peer deps: numpy", numpy.__version__, "numba", numba.__version__, "scipy", scipy.__version__)'
