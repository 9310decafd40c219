#!/usr/bin/env bash
# Installs the Debian packages grainbridge needs (Debian 12). Usage:
#   scripts/install-deps.sh              build + run dependencies (the quickstart needs only these)
#   scripts/install-deps.sh --tests      also what the test suite needs (GoogleTest, Debian's python3,
#                                        ParaView's pvpython, Chromium + chromedriver + Selenium)
#   scripts/install-deps.sh --list base|tests   print one list, one package per line, and exit
# As root it installs what is missing; otherwise it prints the apt-get line to run.
#
# The base list names every package that owns a file the build's find_package calls resolve
# (libraries, include folders, CMake packages and the files their targets reference), not only the
# one a user would think of: liblammps-dev's CMake package stops the configure step unless `lammps`
# provides /usr/bin/lmp (issue 54). The dependency_packages test (tests/build) checks each resolved
# file's owner (dpkg -S) against these lists; a file only the tests resolve may be in --tests.
set -euo pipefail

base=(
  g++ cmake make pkgconf git ca-certificates libc6-dev
  libeigen3-dev
  libhdf5-dev hdf5-helpers libaec-dev zlib1g-dev libcurl4-openssl-dev
  libsqlite3-dev sqlite3 nlohmann-json3-dev
  libopenmpi-dev openmpi-bin
  libcli11-dev libspdlog-dev libfmt-dev libssl-dev libudunits2-dev
  liblapack-dev libblas-dev
  libpetsc-real-dev
  liblammps-dev lammps
  gnuplot-nox fonts-dejavu-core
)
tests=(
  libgtest-dev libgmock-dev python3-minimal
  python3-paraview chromium chromium-driver python3-selenium
)

packages=("${base[@]}")
case "${1:-}" in
  "") ;;
  --tests) packages+=("${tests[@]}") ;;
  --list)
    case "${2:-}" in
      base) printf '%s\n' "${base[@]}" ;;
      tests) printf '%s\n' "${tests[@]}" ;;
      *) echo "usage: $0 --list base|tests" >&2; exit 2 ;;
    esac
    exit 0 ;;
  *) echo "usage: $0 [--tests | --list base|tests]" >&2; exit 2 ;;
esac

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
