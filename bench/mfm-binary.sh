#!/usr/bin/env bash
# Multi-fluid throughput on the Goldschmidt binary bed (issue 26's benchmark): the `bed` stage of
# configs/goldschmidt-binary.json at 1.30 m/s without the rotation model, two solids phases,
# 15 x 45 cells, 5 s simulated, one core, no frames, as bench/mfm-goldschmidt.sh runs the mono
# bed. Last line: wall_seconds_per_simulated_second = X. Target: X <= 30 (the mono bed: 9.81).
#
# Usage: bench/mfm-binary.sh [--duration SECONDS]
set -euo pipefail
exec "$(dirname "${BASH_SOURCE[0]}")/mfm-goldschmidt.sh" --bed binary --duration 5 "$@"
