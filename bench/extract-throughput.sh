#!/usr/bin/env bash
# Extraction throughput on a dense frame of 100,000 particles with their contacts:
#  - Eq. 2.3 coarse graining (bin kernel) onto cells of one mean diameter over the whole box,
#    by a CoarseGrainer reused frame after frame as the extract stage does (contacts_per_s_fresh:
#    the one-shot coarseGrain() call),
#    I/O excluded, one core: contacts_per_s = contacts / median time per call (calls repeated
#    for >= 2 s). Targets: >= 5e6 (goal 2e7).
#  - one pass of the multi-pass MST: mst_100k_seconds, median of 3 (target < 2 s, goal 0.5 s);
#    four passes are timed and printed as well.
#
# The frame: bench/configs/extract-bed.json, a grainbridge `dem` stage that inserts 100,000
# monodisperse spheres at random (solid fraction ~0.32) into a 60 x 60 x 45 d box periodic in x
# and y and lets them settle for 12 sqrt(d/g) (60,000 steps) on a frictional floor, with the
# contact model of bench/dem-vs-lammps.sh. Made once with build-release/bin/grainbridge (or
# $GRAINBRIDGE) and cached under bench/.cache/ (named by the config's hash); later runs reuse it.
#
# Builds nothing. It needs
#   build-release/bin/grainbridge               (or $GRAINBRIDGE): only to generate the frame
#   build-release/bin/grainbridge_bench_extract (or $GRAINBRIDGE_BENCH_EXTRACT): the timings
# made by
#   cmake --preset release -DGRAINBRIDGE_BUILD_BENCH=ON
#   cmake --build build-release --target grainbridge grainbridge_bench_extract
#
# Usage: bench/extract-throughput.sh [--frame FILE.h5] [--regenerate] [--min-seconds S] [--mst-runs N]
#   --frame FILE.h5  time this particle frame instead of the cached bed (nothing is generated)
#   --regenerate     rerun the dem stage even if the cached frame exists
# Environment: GRAINBRIDGE, GRAINBRIDGE_BENCH_EXTRACT (binaries), BENCH_CORE (CPU to pin to, 0).
# Last two lines: contacts_per_s = X, mst_100k_seconds = Y
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
frame=""
regenerate=0
bench_args=()
usage() {
  echo "usage: bench/extract-throughput.sh [--frame FILE.h5] [--regenerate] [--min-seconds S] [--mst-runs N]" >&2
  exit 2
}
while (($#)); do
  case "$1" in
    --frame) [[ $# -ge 2 ]] || usage; frame=$2; shift 2 ;;
    --regenerate) regenerate=1; shift ;;
    --min-seconds | --mst-runs) [[ $# -ge 2 ]] || usage; bench_args+=("$1" "$2"); shift 2 ;;
    *) usage ;;
  esac
done

build_hint="cmake --preset release -DGRAINBRIDGE_BUILD_BENCH=ON && cmake --build build-release --target grainbridge grainbridge_bench_extract"
gb=${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}
bench=${GRAINBRIDGE_BENCH_EXTRACT:-$repo/build-release/bin/grainbridge_bench_extract}
[[ -x "$bench" ]] || {
  echo "no benchmark binary at $bench: build it with '$build_hint' (or set GRAINBRIDGE_BENCH_EXTRACT)" >&2
  exit 2
}
core=${BENCH_CORE:-0}
pin=()
if command -v taskset > /dev/null; then pin=(taskset -c "$core"); fi

if [[ -z "$frame" ]]; then
  config="$repo/bench/configs/extract-bed.json"
  cache="$repo/bench/.cache"
  frame="$cache/extract-bed-$(sha256sum "$config" | cut -c1-12).h5"
  if [[ $regenerate -eq 1 || ! -f "$frame" ]]; then
    [[ -x "$gb" ]] || {
      echo "no grainbridge binary at $gb (needed once, to make the frame): build it with '$build_hint' (or set GRAINBRIDGE)" >&2
      exit 2
    }
    mkdir -p "$cache"
    echo "generating the dense frame: $gb run $config (in $cache; about 20 minutes on one core)" >&2
    force=()
    [[ $regenerate -eq 1 ]] && force=(--force)
    start=$(date +%s)
    (cd "$cache" && "$gb" run "$config" "${force[@]}" >&2)
    # results/<workflow>/<stage>/<key>/frames/particles_<step>.h5: the last step is the settled bed.
    last=$(find "$cache/results/extract-bed/bed" -path '*/frames/particles_*.h5' |
      awk -F'particles_' '{s = $NF; sub(/\.h5$/, "", s); print s + 0, $0}' | sort -n | tail -1 | cut -d' ' -f2-)
    [[ -n "$last" && -f "$last" ]] || { echo "the dem stage wrote no particle frame under $cache/results" >&2; exit 1; }
    cp "$last" "$frame.tmp" && mv "$frame.tmp" "$frame"
    echo "frame generated in $(($(date +%s) - start)) s: $frame (from $last)" >&2
  fi
fi
[[ -f "$frame" ]] || { echo "no frame at $frame" >&2; exit 2; }

echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "load: $(uptime | sed 's/.*load average/load average/')"
echo "grainbridge: $(git -C "$repo" rev-parse --short HEAD 2> /dev/null || echo unknown), $bench, ${pin[*]:-not pinned}"
OMP_NUM_THREADS=1 "${pin[@]}" "$bench" "$frame" "${bench_args[@]}"
