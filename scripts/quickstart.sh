#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to the quickstart workflow's report: installs
# missing packages, builds grainbridge (release), runs configs/quickstart.json.
# Idempotent: a second call rebuilds nothing and finds the workflow cached.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
# Configure until a configure has succeeded: a failed one leaves build-release/CMakeCache.txt but no
# Makefile, and a retry must configure again rather than ask make for a missing Makefile.
if [[ ! -f build-release/Makefile ]]; then
  cmake --preset release >/dev/null
fi
cmake --build build-release -j"$(nproc)" --target grainbridge

status=0
build-release/bin/grainbridge run configs/quickstart.json || status=$?
echo
# The report page's path, then (on a terminal) what it found: DEM against kinetic theory.
build-release/bin/grainbridge report configs/quickstart.json
echo
echo "Database: results/quickstart/grainbridge.sqlite   (sqlite3 results/quickstart/grainbridge.sqlite '.tables')"
echo "Closures: build-release/bin/grainbridge db query --config configs/quickstart.json"
echo "Frames:   results/quickstart/shear/*/particles.xmf   (open in ParaView)"
exit $status
