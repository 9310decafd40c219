#!/usr/bin/env bash
# TF-DEM throughput on the uniform-inflow bed (issue 28's benchmark): configs/goldschmidt-tfdem.json's
# cell_average bed (4000 beads of 2.5 mm, Table 7.1; gas on 15 x 45 cells; dt = t_c/50 = 7.1e-6 s
# and the config's gas step), settled for 0.5 s without the gas (not timed), then 1.92 m/s for 1
# simulated second (timed), on one core, no frames (bench/tfdem-bed.sh does the work). Last line:
# wall_seconds_per_simulated_second = X. Target: <= 60 (5.6e8 particle-steps per simulated second).
#
# Usage: bench/tfdem-goldschmidt.sh [--duration SECONDS]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exec "$repo/bench/tfdem-bed.sh" "$repo/configs/goldschmidt-tfdem.json" --settle 0.5 "$@"
