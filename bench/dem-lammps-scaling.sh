#!/usr/bin/env bash
# engine lammps over ranks (issue 32): one settled 80,000-sphere frictional bed
# (../shared/lammps-bench/in.box, n = 50, nz = 32, settled by LAMMPS and cached by
# bench/lammps/run-lammps-reference.sh) run for 2,000 steps by the dem stage three ways, from the
# same data file and with the same contact law (linear spring-dashpot with tangential history,
# k_n = 2e5, k_t = 2/7 k_n, gamma_n for e = 0.9 at m_eff = 1/2, gamma_t = gamma_n/2, mu = 0.5,
# floor alike, dt = 2e-4, skin 0.3 d, no frames):
#   engine grainbridge on 1 rank;
#   engine lammps on 1 rank (plain `grainbridge run`);
#   engine lammps on 2 ranks (`mpirun -np 3 grainbridge run`, ranks_per_instance 2: rank 0
#   dispatches, ranks 1-2 run the instance).
# Each rate is the run's own throughput line (particle-steps/s over the run phase, set-up
# excluded). The 2-rank efficiency is rate(2 ranks) / (2 rate(1 rank)) of engine lammps.
#
# Builds nothing: build-release/bin/grainbridge (scripts/quickstart.sh builds it) or $GRAINBRIDGE.
# Usage: bench/dem-lammps-scaling.sh [--steps N] [--n N] [--nz NZ]
# Last line: `lammps_2rank_efficiency = X`.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
steps=2000
n=50
nz=32
while (($#)); do
  case "$1" in
    --steps) steps=$2; shift 2 ;;
    --n) n=$2; shift 2 ;;
    --nz) nz=$2; shift 2 ;;
    *) echo "usage: bench/dem-lammps-scaling.sh [--steps N] [--n N] [--nz NZ]" >&2; exit 2 ;;
  esac
done
gb=${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
(($(nproc) >= 2)) || echo "warning: $(nproc) core(s): the 2-rank run shares them" >&2

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
datafile=$("$repo/bench/lammps/run-lammps-reference.sh" --settle-only --n "$n" --nz "$nz" |
  awk -F' = ' '/^lammps_datafile/ {print $2}')
[[ -f "$datafile" ]] || { echo "settled bed ($n x $n x $nz) not found" >&2; exit 1; }
read -r xlo xhi < <(awk '/xlo xhi/ {print $1, $2; exit}' "$datafile")
read -r ylo yhi < <(awk '/ylo yhi/ {print $1, $2; exit}' "$datafile")
read -r zlo zhi < <(awk '/zlo zhi/ {print $1, $2; exit}' "$datafile")
gn=$(awk 'BEGIN {pi = atan2(0, -1); b = -log(0.9) / pi; printf "%.17g", 2 * b * sqrt(2e5 / 0.5) / sqrt(1 + b * b)}')
gt=$(awk -v g="$gn" 'BEGIN {printf "%.17g", g / 2}')
duration=$(awk -v s="$steps" 'BEGIN {printf "%.17g", s * 2e-4}')

# config ENGINE RANKS: the workflow of one run.
config() {
  cat <<JSON
{
  "name": "bench-lammps-scaling",
  "stages": {
    "bed": {"type": "dem", "ranks_per_instance": $2, "params": {
      "engine": "$1", "tangential_model": "lammps_history",
      "box_lo": [$xlo, $ylo, $zlo], "box_hi": [$xhi, $yhi, $zhi], "periodic": "xy",
      "gravity": [0, 0, -1], "dt": 2e-4, "duration": $duration, "frames": 0, "series_points": 1,
      "skin": 0.3, "progress": false,
      "species": [{"name": "grain", "diameter": 1, "density": 1.909859317102744}],
      "lammps_data": "$datafile",
      "lammps_types": [{"type": 1, "species": "grain"}],
      "contact": {"kn": 2e5, "kt": 57142.857142857145, "gamma_n": $gn, "gamma_t": $gt, "mu": 0.5},
      "walls": [{"kind": "plane", "point": [0, 0, 0], "direction": [0, 0, 1],
                 "kn": 2e5, "kt": 57142.857142857145, "gamma_n": $gn, "gamma_t": $gt, "mu": 0.5}]}}
  }
}
JSON
}

# rate TAG ENGINE RANKS: runs it, prints its particle-steps/s.
rate() {
  local dir="$work/$1" log line
  mkdir -p "$dir"
  config "$2" "$3" > "$dir/bench.json"
  if (($3 == 1)); then
    log=$(cd "$dir" && OMP_NUM_THREADS=1 "$gb" run bench.json --force 2>&1) || { echo "$log" >&2; exit 1; }
  else
    log=$(cd "$dir" && OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      OMPI_MCA_rmaps_base_oversubscribe=1 mpirun -np $(($3 + 1)) --oversubscribe "$gb" run bench.json --force 2>&1) ||
      { echo "$log" >&2; exit 1; }
  fi
  line=$(grep -m1 'particle-steps/s' <<<"$log") || { echo "$log" >&2; exit 1; }
  sed -E 's/.*s: ([0-9.e+]+) particle-steps\/s.*/\1/' <<<"$line"
}

echo "bed $n x $n x $nz = $((n * n * nz)) spheres, $steps steps: $datafile"
g1=$(rate gb1 grainbridge 1)
echo "engine grainbridge, 1 rank: $g1 particle-steps/s"
l1=$(rate lmp1 lammps 1)
echo "engine lammps, 1 rank: $l1 particle-steps/s"
l2=$(rate lmp2 lammps 2)
echo "engine lammps, 2 ranks: $l2 particle-steps/s"
awk -v g="$g1" -v l="$l1" 'BEGIN {printf "grainbridge/lammps on 1 rank = %.3f\n", g / l}'
awk -v a="$l1" -v b="$l2" 'BEGIN {printf "lammps_2rank_efficiency = %.3f\n", b / (2 * a)}'
