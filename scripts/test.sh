#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a test run: installs missing packages (with
# ParaView's pvpython for the output test, LAMMPS for the chute comparison, and Chromium,
# chromedriver and Selenium for the report browser test), builds the `ci` preset (RelWithDebInfo,
# assertions on, warnings as errors) and runs the default test set (everything but the `slow` label).
# Extra arguments go to ctest, e.g. scripts/test.sh -L unit   or   scripts/test.sh -R Hdf5
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh --tests
# Configure until a configure has succeeded: a failed one leaves build/CMakeCache.txt but no
# Makefile, and a retry must configure again rather than ask make for a missing Makefile.
if [[ ! -f build/Makefile ]]; then
  cmake --preset ci >/dev/null
fi
cmake --build build -j"$(nproc)"

# MPI tests run as root in CI and on 2 cores with 2+ ranks.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# The packages of the report browser test were installed above: if it cannot start, fail.
export GRAINBRIDGE_REQUIRE_BROWSER=1
ctest --preset ci "$@"
