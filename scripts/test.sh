#!/usr/bin/env bash
# README command 2: install what is missing, build everything and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test
# three.js for the live view's page (web/package-lock.json), from the npm registry.
[ -d web/node_modules/three ] || (cd web && npm ci --no-audit --no-fund)
bash scripts/build.sh -DBUILD_TESTING=ON -DCOSSERAT_BUILD_EXAMPLES=ON -DCOSSERAT_BUILD_BENCHMARKS=ON
ctest --test-dir build --output-on-failure -j"$(nproc)"
