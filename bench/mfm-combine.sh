#!/usr/bin/env bash
# Multi-fluid throughput on the grain-chaff combine (issue 29's benchmark): configs/combine.json,
# 3D, 40 x 8 x 10 cells, grain and chaff fed and carried out, 1 s simulated, one core, no frames,
# as bench/mfm-goldschmidt.sh runs the Goldschmidt beds. Last line:
# wall_seconds_per_simulated_second = X. Target: X <= 120 (the 10 s run within 20 minutes).
#
# Usage: bench/mfm-combine.sh [--duration SECONDS]
set -euo pipefail
exec "$(dirname "${BASH_SOURCE[0]}")/mfm-goldschmidt.sh" --bed combine --duration 1 "$@"
