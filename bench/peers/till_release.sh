#!/usr/bin/env bash
# Builds the hand-optimised C++ dynamics example of Till, Aloi & Rucker (2019),
# github.com/JohnDTill/ContinuumRobotExamples, 02_Dynamics/00_Cosserat_Rod_PDE/Cpp_overoptimized/main.cpp
# ("Cosserat_Rod_PDE_Overoptimized"), set to the peer release problem P1 of BENCHMARKS.md
# (examples/cantilever_release.json). Their code is copied to a temporary directory and edited
# there; nothing of theirs is stored in this repository.
#
#   bash bench/peers/till_release.sh --src /work/peers/ContinuumRobotExamples --out /tmp/till_release \
#        [--alpha 0] [--sos-tol 1e-12] [--fix-gravity] [--plain]
#
# --out      the binary to write (default /tmp/till_release)
# --alpha    their BDF-alpha parameter. Their file ships alpha = -0.2 (numerically damped);
#            the default here is 0, which is exactly BDF2, our time scheme
#            (c0 = (1.5+alpha)/(dt(1+alpha)) = 1.5/dt, history -2/dt z_n + 0.5/dt z_{n-1}).
# --sos-tol  their Levenberg-Marquardt stop: sum of squares of the tip residual [n(L); m(L)]
#            (N^2 + (N m)^2) <= sos-tol, for the initial equilibrium and every step. Theirs:
#            1e-12 (kept by default). Ours, solver.tolerance 1e-10 on the residual scaled by
#            EI/L^2 (forces) and EI/L (moments), is |n| <~ 6e-11 N, |m| <~ 3e-11 N m here,
#            i.e. about --sos-tol 1e-21.
# --fix-gravity  the hand-optimised file writes n in the body frame but subtracts R*rhoAg where
#            R^T*rhoAg is meant (its plain twin, Cpp/main.cpp, works in the world frame and is
#            right). The option writes R^T (same cost). Off by default: their code as shipped.
# --nodes    their grid points N (default 40, P1's); other values only to study their Euler-in-s
#            discretisation error (the accuracy check of bench/peers/README.md).
# --plain    build their plain (Eigen-expression) version Cpp/main.cpp instead, with the same
#            substitutions (it has no gravity slip).
#
# Run:  /tmp/till_release [TRAJ.csv]   prints their own timing of the time loop ("Time elasped",
# "Real-time ratio", std::clock, i.e. CPU time). With an argument, after the timed loop and
# the clock, it writes the tip trajectory "t,x,z" (m) at t = 0, dt, ..., T - dt to TRAJ.csv
# (their loop records each state before solving the next step, and only x and z).
# Without an argument the program writes no file at all (as shipped: it only fills px, pz in memory).
set -euo pipefail

SRC=""; OUT=/tmp/till_release; NODES=40; ALPHA=0; SOS_TOL=1e-12; FIX_GRAVITY=0; PLAIN=0
CXX=${CXX:-g++}
while [ $# -gt 0 ]; do
  case "$1" in
    --src) SRC=$2; shift 2;;
    --out) OUT=$2; shift 2;;
    --nodes) NODES=$2; shift 2;;
    --alpha) ALPHA=$2; shift 2;;
    --sos-tol) SOS_TOL=$2; shift 2;;
    --fix-gravity) FIX_GRAVITY=1; shift;;
    --plain) PLAIN=1; shift;;
    *) echo "unknown argument: $1" >&2; exit 2;;
  esac
done
[ -n "$SRC" ] || { echo "usage: $0 --src DIR/ContinuumRobotExamples [--out BIN] [--alpha A] [--sos-tol T] [--fix-gravity] [--plain]" >&2; exit 2; }

EX=$SRC/02_Dynamics/00_Cosserat_Rod_PDE
if [ "$PLAIN" = 1 ]; then MAIN=$EX/Cpp/main.cpp; else MAIN=$EX/Cpp_overoptimized/main.cpp; fi
[ -f "$MAIN" ] || { echo "not found: $MAIN" >&2; exit 2; }

TMP=$(mktemp -d /tmp/till_build.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/Library" "$TMP/app"
cp "$SRC"/Library/*.h "$TMP/Library/"
# Their Library/eigen is an empty git submodule; use Debian's Eigen (libeigen3-dev).
ln -s /usr/include/eigen3 "$TMP/Library/eigen"
cp "$MAIN" "$TMP/app/main.cpp"

# subst OLD NEW: replace an exact line fragment that must occur exactly once.
subst() {
  python3 - "$TMP/app/main.cpp" "$1" "$2" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
n = text.count(old)
if n != 1:
    sys.exit(f"till_release.sh: expected exactly one '{old}' in their main.cpp, found {n}")
open(path, "w").write(text.replace(old, new))
PY
}

# 1. The problem. Their file already ships P1's parameters; each is re-set here so that a
#    change upstream fails loudly instead of silently changing the problem.
subst 'const double E = 200e9;'   'const double E = 200e9;'      # Young's modulus, Pa
subst 'const double G = 80e9;'    'const double G = 80e9;'       # shear modulus, Pa
subst 'const double rad = 0.001;' 'const double rad = 0.001;'    # radius, m
subst 'const double rho = 8000;'  'const double rho = 8000;'     # density, kg/m^3
subst 'const Vector3d g = -9.81*Vector3d::UnitX();' 'const Vector3d g = -9.81*Vector3d::UnitX();'  # gravity along -x
subst 'const double L = 0.5;'     'const double L = 0.5;'        # length, m (clamped at 0 along +z, R = I)
subst 'const int N = 40;'         "const int N = $NODES;"        # grid points (P1: 40, 39 Euler steps in s)
subst 'const double dt = 2e-3;'   'const double dt = 2e-3;'      # time step, s
subst 'const double T = 25;'      'const double T = 25;'         # simulated time, s (12 500 steps)
subst 'const double initial_tip_mass = 0.02;' 'const double initial_tip_mass = 0.02;'  # preload 0.02 kg * g at the tip, removed at t = 0+
for b in Bs Be Bb Bt; do subst "const double $b = 0;" "const double $b = 0;"; done   # no damping
# 2. Time scheme: alpha (see --alpha).
subst 'const double alpha = -0.2;' "const double alpha = $ALPHA;"
# 3. Solver tolerance (see --sos-tol), for the initial equilibrium and for every step.
subst 'solveLevenbergMarquardt<objFunc<false> >(guess);' "solveLevenbergMarquardt<objFunc<false> >(guess, $SOS_TOL);"
subst 'solveLevenbergMarquardt<objFunc<true> >(reaction_wrench);' "solveLevenbergMarquardt<objFunc<true> >(reaction_wrench, $SOS_TOL);"
# 4. Gravity in the body frame (see --fix-gravity).
if [ "$FIX_GRAVITY" = 1 ]; then
  [ "$PLAIN" = 0 ] || { echo "--fix-gravity applies to the hand-optimised file only" >&2; exit 2; }
  subst '- R00*rhoAg(0) - R01*rhoAg(1) - R02*rhoAg(2);' '- R00*rhoAg(0) - R10*rhoAg(1) - R20*rhoAg(2);'
  subst '- R10*rhoAg(0) - R11*rhoAg(1) - R12*rhoAg(2);' '- R01*rhoAg(0) - R11*rhoAg(1) - R21*rhoAg(2);'
  subst '- R20*rhoAg(0) - R21*rhoAg(1) - R22*rhoAg(2);' '- R02*rhoAg(0) - R12*rhoAg(1) - R22*rhoAg(2);'
fi
# 5. Optional tip trajectory file, written after their timed loop (see "Run" above).
subst 'int main(int, char**){' 'int main(int argc, char** argv){'
subst '    #ifdef QT_CORE_LIB
    playAnimation' '    if(argc > 1){
        FILE* traj = fopen(argv[1], "w");
        if(!traj){ std::cerr << "cannot write " << argv[1] << std::endl; return 2; }
        fprintf(traj, "t,x,z\n");
        for(int i = 0; i < M; i++) fprintf(traj, "%.6f,%.17g,%.17g\n", i*dt, px(i,N-1), pz(i,N-1));
        fclose(traj);
    }

    #ifdef QT_CORE_LIB
    playAnimation'

# Same optimisation flags as our Release build (CMAKE_CXX_FLAGS_RELEASE: -O3 -DNDEBUG, no -march).
"$CXX" -std=c++17 -O3 -DNDEBUG -I"$TMP/Library" "$TMP/app/main.cpp" -o "$OUT"
echo "built $OUT from $MAIN (N $NODES, alpha $ALPHA, sos_tol $SOS_TOL, fix_gravity $FIX_GRAVITY)" >&2
