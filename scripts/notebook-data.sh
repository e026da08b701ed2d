#!/usr/bin/env bash
# Regenerate every CSV of notebooks-data/ (or of the directory given) from the example programs
# of an existing build (build/examples/, built with -DCOSSERAT_BUILD_EXAMPLES=ON, the default).
#   bash scripts/notebook-data.sh [output_dir]        (default: notebooks-data)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-notebooks-data}"
mkdir -p "$out"
ex=build/examples
"$ex/tendon_robot" robots/tendon_three_tendon.json "$out"           # tendon_shapes, tendon_jacobian
"$ex/buckling_sweep" "$out"                                          # buckling_band_sweep
"$ex/jamming_patterns" robots/jamming_virtual_joints.json "$out"     # jamming_patterns
"$ex/jamming_workspace" robots/jamming_virtual_joints.json "$out"    # jamming_workspace
"$ex/eversion_growth" "$out"                                         # eversion_{plain,banded}_{shapes,tip}
"$ex/eversion_bend_radius" robots/eversion_banded_vine.json "$out"   # eversion_bend_radius
