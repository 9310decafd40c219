#!/usr/bin/env bash
# The fluid solver petsc on one rank against the solvers a config ships with (issue 58): the bed
# of bench/mfm-goldschmidt.sh (--bed mono: the 2D Goldschmidt bed, whose band LU is 15 wide; --bed
# combine: configs/combine.json, 3D, 40 x 8 x 10, BiCGSTAB for momentum and pressure) run three
# times in one invocation on one core: as shipped, with `pressure_solver` petsc (the default
# pressure_petsc_options: BiCGSTAB with point Jacobi), and with every family petsc. Prints each run's
# wall time per simulated second and, last, `petsc_pressure_over_shipped = X` (X < 1: PETSc's
# pressure solve is the faster).
#
# Usage: bench/mfm-petsc.sh [--bed mono|combine] [--duration SECONDS]
# Last line: petsc_pressure_over_shipped = X
set -euo pipefail
here=$(dirname "${BASH_SOURCE[0]}")
bed=combine
duration=0.1
while (($#)); do
  case "$1" in
    --bed) bed=$2; shift 2 ;;
    --duration) duration=$2; shift 2 ;;
    *) echo "usage: bench/mfm-petsc.sh [--bed mono|combine] [--duration SECONDS]" >&2; exit 2 ;;
  esac
done
declare -A wall
for variant in shipped pressure all; do
  sets=()
  case "$variant" in
    pressure) sets=(--set pressure_solver=petsc) ;;
    all) sets=(--set momentum_solver=petsc --set pressure_solver=petsc --set fraction_solver=petsc) ;;
  esac
  echo "== $variant"
  out=$("$here/mfm-goldschmidt.sh" --bed "$bed" --duration "$duration" ${sets[@]+"${sets[@]}"})
  echo "$out" | grep -v '^machine\|^grainbridge'
  wall[$variant]=$(echo "$out" | sed -n 's/^wall_seconds_per_simulated_second = //p')
done
python3 - "${wall[shipped]}" "${wall[pressure]}" "${wall[all]}" <<'PY'
import sys
shipped, pressure, every = map(float, sys.argv[1:])
print(f"every family petsc over shipped: {every / shipped:.3f}")
print(f"petsc_pressure_over_shipped = {pressure / shipped:.3f}")
PY
