#!/usr/bin/env bash
# DEM throughput against LAMMPS on the same dense frictional bed (issue 4's benchmark):
# 20,000 monodisperse spheres settled by LAMMPS (../shared/lammps-bench/in.box), then LAMMPS
# (in.timed) and grainbridge each read the same data file and run 10,000 steps with no output:
# linear spring-dashpot with tangential history, k_n = 2e5, k_t = 2/7 k_n, gamma_n for e = 0.9
# at m_eff = m/2, gamma_t = gamma_n/2, mu = 0.5 (particles and floor alike), dt = 2e-4, skin
# 0.3 d, one core, one thread each, interleaved runs, medians.
#
# Builds nothing: it uses build-release/bin/grainbridge (scripts/quickstart.sh builds it) or
# $GRAINBRIDGE. Installs Debian's lammps package if missing (bench/lammps/run-lammps-reference.sh).
#
# Usage: bench/dem-vs-lammps.sh [--runs N]
# Last line: ratio grainbridge/lammps = X   (particle-steps per second)
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=3
while (($#)); do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: bench/dem-vs-lammps.sh [--runs N]" >&2; exit 2 ;;
  esac
done
gb=${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
core=$(($(nproc) - 1))

lmp_ref="$repo/bench/lammps/run-lammps-reference.sh"
datafile=$("$lmp_ref" --settle-only | awk -F' = ' '/^lammps_datafile/ {print $2}')
[[ -f "$datafile" ]] || { echo "settled bed not found" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The box comes from the data file; gamma_n as in.box computes it (e = 0.9 at m_eff = 1/2).
read -r xlo xhi < <(awk '/xlo xhi/ {print $1, $2; exit}' "$datafile")
read -r ylo yhi < <(awk '/ylo yhi/ {print $1, $2; exit}' "$datafile")
read -r zlo zhi < <(awk '/zlo zhi/ {print $1, $2; exit}' "$datafile")
gn=$(awk 'BEGIN {pi = atan2(0, -1); b = -log(0.9) / pi; printf "%.17g", 2 * b * sqrt(2e5 / 0.5) / sqrt(1 + b * b)}')
gt=$(awk -v g="$gn" 'BEGIN {printf "%.17g", g / 2}')
cat > "$work/bench.json" <<JSON
{
  "name": "bench-dense-bed",
  "stages": {
    "bed": {"type": "dem", "params": {
      "box_lo": [$xlo, $ylo, $zlo], "box_hi": [$xhi, $yhi, $zhi], "periodic": "xy",
      "gravity": [0, 0, -1], "dt": 2e-4, "duration": 2.0, "frames": 0, "series_points": 1,
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

median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
: > "$work/gb.rates"; : > "$work/lmp.rates"; : > "$work/gb.contacts"; : > "$work/lmp.contacts"
echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "grainbridge: $gb ($(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)), core $core"
for ((r = 1; r <= runs; r++)); do
  out=$("$lmp_ref" --runs 1 --datafile "$datafile")
  lr=$(awk -F' = ' '/^lammps_particle_steps_per_s/ {print $2}' <<<"$out")
  lc=$(awk -F' = ' '/^lammps_contacts_per_particle/ {print $2}' <<<"$out")
  echo "$lr" >> "$work/lmp.rates"; echo "$lc" >> "$work/lmp.contacts"
  log=$(cd "$work" && OMP_NUM_THREADS=1 taskset -c "$core" "$gb" run bench.json --force 2>&1)
  line=$(grep -m1 'particle-steps/s' <<<"$log") || { echo "$log" >&2; exit 1; }
  gr=$(sed -E 's/.*s: ([0-9.e+]+) particle-steps\/s.*/\1/' <<<"$line")
  gc=$(sed -E 's/.*, ([0-9.]+) contacts per particle.*/\1/' <<<"$line")
  echo "$gr" >> "$work/gb.rates"; echo "$gc" >> "$work/gb.contacts"
  echo "run $r: lammps $lr particle-steps/s ($lc contacts/particle), grainbridge $gr particle-steps/s ($gc contacts/particle)"
done
lm=$(median < "$work/lmp.rates"); gm=$(median < "$work/gb.rates")
echo "lammps median: $lm particle-steps/s, contacts per particle $(median < "$work/lmp.contacts")"
echo "grainbridge median: $gm particle-steps/s, contacts per particle $(median < "$work/gb.contacts")"
awk -v g="$gm" -v l="$lm" 'BEGIN {printf "ratio grainbridge/lammps = %.3f\n", g / l}'
