#!/usr/bin/env bash
# Multi-fluid throughput on the Goldschmidt binary bed (issues 26 and 55): the `bed` stage of
# configs/goldschmidt-binary.json at 1.30 m/s without the rotation model, two solids phases,
# 15 x 45 cells, and in the same invocation the monodisperse bed of bench/mfm-goldschmidt.sh
# (1.92 m/s, one solids phase, the same grid), each 5 s simulated on one core, no frames. The
# binary bed solves a third momentum system and the solids-solids drag, so it costs more per
# step; issue 55 asks that it cost at most 1.8 times the mono bed per simulated second.
#
# Usage: bench/mfm-binary.sh [--duration SECONDS] (further arguments go to both runs)
# Last lines: wall_seconds_per_simulated_second of each bed, then binary_over_mono = X
# (wall time per simulated second, binary over mono). Target: X <= 1.8.
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
duration=5
args=()
while (($#)); do
  case "$1" in
    --duration) duration=$2; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
echo "== mono bed (bench/mfm-goldschmidt.sh --bed mono --duration $duration)"
mono=$("$here/mfm-goldschmidt.sh" --bed mono --duration "$duration" "${args[@]}" | tee -a /dev/stderr | tail -1)
echo "== binary bed (bench/mfm-goldschmidt.sh --bed binary --duration $duration)"
binary=$("$here/mfm-goldschmidt.sh" --bed binary --duration "$duration" "${args[@]}" | tee -a /dev/stderr | tail -1)
mono=${mono##*= }
binary=${binary##*= }
echo "mono: wall_seconds_per_simulated_second = $mono"
echo "binary: wall_seconds_per_simulated_second = $binary"
python3 -c "import sys; print(f'binary_over_mono = {float(sys.argv[1]) / float(sys.argv[2]):.2f}')" "$binary" "$mono"
