#!/usr/bin/env bash
# Builds the fastest C++ inverse-kinematics example of the continuum Stewart-Gough robot of
# Till, Aloi & Rucker (2019), github.com/JohnDTill/ContinuumRobotExamples,
# 01_Statics/03_CSG_IK_Speedup/Cpp_5/main.cpp, with its Levenberg-Marquardt stop (a sum of
# squares of its residual, m, rad, N, N m; theirs 1e-6) set by --sos-tol. Their code is copied to
# a temporary directory; nothing of theirs is stored in this repository.
#
#   bash bench/peers/till_csg_ik.sh --src /work/peers/ContinuumRobotExamples --out /tmp/till_csg \
#        [--sos-tol 1e-6]
#
# Run: /tmp/till_csg   prints "Time elasped" (std::clock, CPU) and "Solution rate" for 50 000
# warm-started solves (bench/bench_stewart_gough_ik.cpp runs the same loop on ours).
set -euo pipefail
SRC=""; OUT=/tmp/till_csg; SOS_TOL=1e-6
CXX=${CXX:-g++}
while [ $# -gt 0 ]; do
  case "$1" in
    --src) SRC=$2; shift 2;;
    --out) OUT=$2; shift 2;;
    --sos-tol) SOS_TOL=$2; shift 2;;
    *) echo "unknown argument: $1" >&2; exit 2;;
  esac
done
[ -n "$SRC" ] || { echo "usage: $0 --src DIR/ContinuumRobotExamples [--out BIN] [--sos-tol T]" >&2; exit 2; }
MAIN=$SRC/01_Statics/03_CSG_IK_Speedup/Cpp_5/main.cpp
[ -f "$MAIN" ] || { echo "not found: $MAIN" >&2; exit 2; }
TMP=$(mktemp -d /tmp/till_csg_build.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/Library" "$TMP/app"
cp "$SRC"/Library/*.h "$TMP/Library/"
ln -s /usr/include/eigen3 "$TMP/Library/eigen"  # their Library/eigen is an empty submodule
# Their three solves share one stop; it must occur exactly three times.
python3 - "$MAIN" "$TMP/app/main.cpp" "$SOS_TOL" <<'PY'
import sys
src, dst, tol = sys.argv[1:4]
text = open(src).read()
old = "(guess, 1e-6, 500, 1e-4, 0.5)"
if text.count(old) != 3:
    sys.exit(f"till_csg_ik.sh: expected their stop '{old}' three times, found {text.count(old)}")
open(dst, "w").write(text.replace(old, f"(guess, {tol}, 500, 1e-4, 0.5)"))
PY
# Same optimisation flags as our Release build (-O3 -DNDEBUG, no -march).
"$CXX" -std=c++17 -O3 -DNDEBUG -I"$TMP/Library" "$TMP/app/main.cpp" -o "$OUT"
echo "built $OUT from $MAIN (sos_tol $SOS_TOL)" >&2
