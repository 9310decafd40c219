#!/usr/bin/env bash
# Installs the Debian packages grainbridge needs (Debian 12). Usage:
#   scripts/install-deps.sh            build + run dependencies
#   scripts/install-deps.sh --tests    also what the test suite needs (ParaView's pvpython, LAMMPS,
#                                      Chromium + chromedriver + Selenium for the report browser test)
# As root it installs what is missing; otherwise it prints the apt-get line to run.
set -euo pipefail

packages=(
  g++ cmake make pkg-config git ca-certificates
  libeigen3-dev libhdf5-dev libsqlite3-dev sqlite3 nlohmann-json3-dev
  libopenmpi-dev openmpi-bin libcli11-dev libspdlog-dev libssl-dev
  libudunits2-dev gnuplot-nox fonts-dejavu-core liblapack-dev
  liblammps-dev
  libgtest-dev libgmock-dev
)
if [[ "${1:-}" == "--tests" ]]; then
  packages+=(python3-paraview lammps chromium chromium-driver python3-selenium)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "grainbridge needs these Debian packages: ${missing[*]}" >&2
if [[ $(id -u) -ne 0 ]]; then
  echo "run as root:  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "installed: ${missing[*]}" >&2
