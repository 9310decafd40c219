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
# Then two dilute sheared boxes, closure-sweep style (bench/lammps/in.shear-gas): 2,000 spheres in
# a periodic cube, no gravity, the same contact law, sheared at rate 1 (d = m = 1 units) for
# 20,000 steps: LAMMPS with fix deform xy erate, remap v; grainbridge with its Lees-Edwards
# boundaries (shear_rate). Both read the same LAMMPS-prepared gas. One at solid fraction 0.15
# with friction 0.5, one at 0.05 frictionless (mu 0), as the closure loop's dilute boxes (issue 59).
#
# Usage: bench/dem-vs-lammps.sh [--runs N] [--scaling]     (N: 5 by default; issue 33 found 3 too few)
#   --scaling  also times 5,000 (n 25, nz 8) and 80,000 (n 50, nz 32) beds, settled the same way,
#              and says for each engine whether its rate is flat: rate(80k) >= 0.85 x rate(5k).
# Last three lines: `dilute frictionless box (phi 0.05): ratio grainbridge/lammps = Z`,
#                   `dilute sheared box: ratio grainbridge/lammps = Y` (phi 0.15, mu 0.5), then
#                   `ratio grainbridge/lammps = X`   (particle-steps per second, the 20,000 bed)
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=5
scaling=0
while (($#)); do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --scaling) scaling=1; shift ;;
    *) echo "usage: bench/dem-vs-lammps.sh [--runs N] [--scaling]" >&2; exit 2 ;;
  esac
done
gb=${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
core=$(($(nproc) - 1))
lmp_ref="$repo/bench/lammps/run-lammps-reference.sh"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The contact law of both beds: gamma_n as in.box computes it (e = 0.9 at m_eff = 1/2), gamma_t
# half of it.
gn=$(awk 'BEGIN {pi = atan2(0, -1); b = -log(0.9) / pi; printf "%.17g", 2 * b * sqrt(2e5 / 0.5) / sqrt(1 + b * b)}')
gt=$(awk -v g="$gn" 'BEGIN {printf "%.17g", g / 2}')
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

# time_bed N NZ: settle (or find) the N x N x NZ bed, time both engines on it `runs` times,
# interleaved, and leave the medians in $work/N-NZ.{gb,lmp} (particle-steps per second).
time_bed() {
  local n=$1 nz=$2 tag="$1-$2" datafile xlo xhi ylo yhi zlo zhi r out lr lc log line gr gc
  datafile=$("$lmp_ref" --settle-only --n "$n" --nz "$nz" | awk -F' = ' '/^lammps_datafile/ {print $2}')
  [[ -f "$datafile" ]] || { echo "settled bed ($n x $n x $nz) not found" >&2; exit 1; }
  # The box comes from the data file.
  read -r xlo xhi < <(awk '/xlo xhi/ {print $1, $2; exit}' "$datafile")
  read -r ylo yhi < <(awk '/ylo yhi/ {print $1, $2; exit}' "$datafile")
  read -r zlo zhi < <(awk '/zlo zhi/ {print $1, $2; exit}' "$datafile")
  mkdir -p "$work/$tag"
  cat > "$work/$tag/bench.json" <<JSON
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
  : > "$work/$tag/gb.rates"; : > "$work/$tag/lmp.rates"; : > "$work/$tag/gb.contacts"; : > "$work/$tag/lmp.contacts"
  echo "bed $n x $n x $nz = $((n * n * nz)) spheres: $datafile"
  for ((r = 1; r <= runs; r++)); do
    out=$("$lmp_ref" --runs 1 --datafile "$datafile")
    lr=$(awk -F' = ' '/^lammps_particle_steps_per_s/ {print $2}' <<<"$out")
    lc=$(awk -F' = ' '/^lammps_contacts_per_particle/ {print $2}' <<<"$out")
    echo "$lr" >> "$work/$tag/lmp.rates"; echo "$lc" >> "$work/$tag/lmp.contacts"
    log=$(cd "$work/$tag" && OMP_NUM_THREADS=1 taskset -c "$core" "$gb" run bench.json --force 2>&1)
    line=$(grep -m1 'particle-steps/s' <<<"$log") || { echo "$log" >&2; exit 1; }
    gr=$(sed -E 's/.*s: ([0-9.e+]+) particle-steps\/s.*/\1/' <<<"$line")
    gc=$(sed -E 's/.*, ([0-9.]+) contacts per particle.*/\1/' <<<"$line")
    echo "$gr" >> "$work/$tag/gb.rates"; echo "$gc" >> "$work/$tag/gb.contacts"
    echo "  run $r: lammps $lr particle-steps/s ($lc contacts/particle), grainbridge $gr particle-steps/s ($gc contacts/particle)"
  done
  median < "$work/$tag/lmp.rates" > "$work/$tag.lmp"
  median < "$work/$tag/gb.rates" > "$work/$tag.gb"
  median < "$work/$tag/lmp.contacts" > "$work/$tag.lmp.contacts"
  median < "$work/$tag/gb.contacts" > "$work/$tag.gb.contacts"
  echo "  lammps median: $(cat "$work/$tag.lmp") particle-steps/s, contacts per particle $(median < "$work/$tag/lmp.contacts")"
  echo "  grainbridge median: $(cat "$work/$tag.gb") particle-steps/s, contacts per particle $(median < "$work/$tag/gb.contacts")"
  awk -v g="$(cat "$work/$tag.gb")" -v l="$(cat "$work/$tag.lmp")" 'BEGIN {printf "  ratio on this bed: %.3f\n", g / l}'
}

# time_gas: prepare (or find) the sheared gas's start, time both engines on it `runs` times,
# interleaved, and leave the medians in $work/gas.{gb,lmp}.
# time_gas PHI MU TAG: time both engines on the 2,000-sphere gas at solid fraction PHI and
# friction MU, `runs` times, interleaved; medians in $work/TAG.{gb,lmp}.
time_gas() {
  local phi=$1 mu=$2 tag=$3 lmp="" c datafile L r log lr gr line glog
  # The names run-lammps-reference.sh looks for; the dense bed, timed first, installed the package.
  for c in lmp lmp_serial lmp_mpi lmp_stable; do
    if command -v "$c" > /dev/null 2>&1; then lmp=$(command -v "$c"); break; fi
  done
  [[ -n "$lmp" ]] || { echo "no LAMMPS binary (lmp, lmp_serial, lmp_mpi, lmp_stable)" >&2; exit 1; }
  datafile="$repo/bench/lammps/.cache/gas-n2000-phi$phi.data"
  mkdir -p "$(dirname "$datafile")" "$work/$tag"
  if [[ ! -s "$datafile" ]]; then
    (cd "$work/$tag" && OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      "$lmp" -in "$repo/bench/lammps/in.shear-gas" -var prepare 1 -var datafile "$datafile.partial" \
      -var phi "$phi" -screen none -log prepare.log) ||
      { echo "preparing the gas failed: $work/$tag/prepare.log" >&2; exit 1; }
    mv "$datafile.partial" "$datafile"
  fi
  L=$(awk '/xlo xhi/ {print $2; exit}' "$datafile")
  cat > "$work/$tag/bench.json" <<JSON
{
  "name": "bench-sheared-gas",
  "stages": {
    "gas": {"type": "dem", "params": {
      "box_lo": [0, 0, 0], "box_hi": [$L, $L, $L], "periodic": "xyz",
      "gravity": [0, 0, 0], "shear_rate": 1.0, "dt": 2e-4, "duration": 4.0, "frames": 0, "series_points": 1,
      "skin": 0.3, "progress": false,
      "species": [{"name": "grain", "diameter": 1, "density": 1.909859317102744}],
      "lammps_data": "$datafile",
      "lammps_types": [{"type": 1, "species": "grain"}],
      "contact": {"kn": 2e5, "kt": 57142.857142857145, "gamma_n": $gn, "gamma_t": $gt, "mu": $mu}}}
  }
}
JSON
  : > "$work/$tag.gb.rates"; : > "$work/$tag.lmp.rates"
  echo "dilute sheared box, 2000 spheres at solid fraction $phi, friction $mu: $datafile"
  for ((r = 1; r <= runs; r++)); do
    log="$work/$tag/timed-$r.log"
    (cd "$work/$tag" && OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 taskset -c "$core" \
      "$lmp" -in "$repo/bench/lammps/in.shear-gas" -var datafile "$datafile" -var phi "$phi" -var mu "$mu" \
      -screen none -log "$log") ||
      { echo "LAMMPS sheared gas failed: $log" >&2; exit 1; }
    # "Loop time of 2.9 on 1 procs for 20000 steps with 2000 atoms"
    lr=$(awk '/^Loop time of/ {printf "%.6g", $12 * $9 / $4; exit}' "$log")
    echo "$lr" >> "$work/$tag.lmp.rates"
    # The whole log first: grep -m1 in the pipe would close it early, and pipefail would see
    # grainbridge die of SIGPIPE.
    glog=$(cd "$work/$tag" && OMP_NUM_THREADS=1 taskset -c "$core" "$gb" run bench.json --force 2>&1) ||
      { echo "$glog" >&2; echo "grainbridge sheared gas failed" >&2; exit 1; }
    line=$(grep -m1 'particle-steps/s' <<<"$glog") || { echo "$glog" >&2; exit 1; }
    gr=$(sed -E 's/.*s: ([0-9.e+]+) particle-steps\/s.*/\1/' <<<"$line")
    echo "$gr" >> "$work/$tag.gb.rates"
    echo "  run $r: lammps $lr particle-steps/s, grainbridge $gr particle-steps/s"
  done
  median < "$work/$tag.lmp.rates" > "$work/$tag.lmp"
  median < "$work/$tag.gb.rates" > "$work/$tag.gb"
  echo "  lammps median: $(cat "$work/$tag.lmp") particle-steps/s; grainbridge median: $(cat "$work/$tag.gb") particle-steps/s"
}

echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
# The binary's own version line (its git SHA and dirty flag), not the checkout's HEAD: GRAINBRIDGE
# may point at another build.
echo "grainbridge: $gb ($("$gb" --version 2>/dev/null | head -1 || echo unknown)), core $core"
if ((scaling)); then
  time_bed 25 8
  time_bed 50 32
fi
time_bed 25 32
if ((scaling)); then
  # Flat: the rate per particle-step does not fall with system size (cache misses, list rebuilds).
  # The 5k bed is only 8 layers deep, so more of it is free surface with fewer contacts per
  # particle: the rate per contact-step (rate x contacts per particle) is printed beside it.
  for engine in lmp gb; do
    awk -v name="$([[ $engine == gb ]] && echo grainbridge || echo lammps)" -v small="$(cat "$work/25-8.$engine")" \
        -v big="$(cat "$work/50-32.$engine")" -v zs="$(cat "$work/25-8.$engine.contacts")" \
        -v zb="$(cat "$work/50-32.$engine.contacts")" 'BEGIN {
      f = big / small
      printf "scaling %s: rate(80k) / rate(5k) = %.3f (%s); per contact-step %.3f\n", name, f,
             (f >= 0.85) ? "flat" : "not flat, below 0.85", f * zb / zs
    }'
  done
fi
time_gas 0.15 0.5 gas
time_gas 0.05 0 gas005
awk -v g="$(cat "$work/gas005.gb")" -v l="$(cat "$work/gas005.lmp")" \
  'BEGIN {printf "dilute frictionless box (phi 0.05): ratio grainbridge/lammps = %.3f\n", g / l}'
awk -v g="$(cat "$work/gas.gb")" -v l="$(cat "$work/gas.lmp")" 'BEGIN {printf "dilute sheared box: ratio grainbridge/lammps = %.3f\n", g / l}'
awk -v g="$(cat "$work/25-32.gb")" -v l="$(cat "$work/25-32.lmp")" 'BEGIN {printf "ratio grainbridge/lammps = %.3f\n", g / l}'
