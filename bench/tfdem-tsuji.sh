#!/usr/bin/env bash
# TF-DEM throughput on the central-jet bed (issue 27's benchmark): configs/tsuji-jet-tfdem.json's
# bed (2400 beads of 4 mm, Table 7.1; gas on 15 x 45 cells; dt = t_c/50 = 1.5e-5 s and the
# config's gas step), settled for 0.5 s without the gas (not timed), then the jet for 1 simulated
# second (timed), on one core, no frames (bench/tfdem-bed.sh does the work). Last line:
# wall_seconds_per_simulated_second = X. Target: <= 30 (the reference's 339 on an Opteron 270,
# line 1940; MFiX-DEM 21.3.2: 58.5).
#
# Usage: bench/tfdem-tsuji.sh [--duration SECONDS]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exec "$repo/bench/tfdem-bed.sh" "$repo/configs/tsuji-jet-tfdem.json" --settle 0.5 "$@"
