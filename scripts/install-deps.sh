#!/usr/bin/env bash
# Installs the Debian 12 packages cosserat needs to build, benchmark and plot; with --test, also
# what only the test suite reads (python3-vtk9: the VTK time series read back with VTK;
# python3-venv, -pip, -setuptools, -wheel: `pip install .` into a fresh virtual environment;
# python3-nbconvert, python3-ipykernel: the notebooks of examples/notebooks run top to bottom;
# chromium, chromium-driver, python3-selenium, and npm when there is none: the live view's
# end-to-end test in headless Chromium, with three.js from npm; ffmpeg: animations as MP4;
# libopenmpi-dev, openmpi-bin: sweeps over MPI ranks, and their test).
# Run as root (or with sudo). Safe to run again: apt skips what is already there.
set -euo pipefail
packages=(
  build-essential cmake
  libeigen3-dev libceres-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev
  python3 python3-dev python3-numpy python3-matplotlib pybind11-dev
)
if [ "${1:-}" = "--test" ]; then
  packages+=(python3-vtk9 python3-venv python3-pip python3-setuptools python3-wheel
             python3-nbconvert python3-ipykernel chromium chromium-driver python3-selenium ffmpeg
             libopenmpi-dev openmpi-bin)
  # Debian's npm, unless a Node.js with its own npm is installed (nodesource's conflicts).
  command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
