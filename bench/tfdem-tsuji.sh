#!/usr/bin/env bash
# TF-DEM throughput on the central-jet bed (issue 27's benchmark): configs/tsuji-jet-tfdem.json's
# bed (2400 beads of 4 mm, Table 7.1; gas on 15 x 45 cells; dt = t_c/50 = 1.5e-5 s, a gas step of
# 10 DEM steps), settled for 0.5 s without the gas (not timed), then the jet for 1 simulated
# second (timed: the stage's own timing of its run phase), on one core, no frames. Prints
# particle-steps per second and gas steps per second, and last the wall time per simulated
# second. Target: <= 30 (the reference's 339 on an Opteron 270, line 1940; MFiX-DEM 21.3.2: 58.5).
#
# Builds nothing: it uses build-release/bin/grainbridge (scripts/quickstart.sh builds it) or
# $GRAINBRIDGE.
#
# Usage: bench/tfdem-tsuji.sh [--duration SECONDS]
# Last line: wall_seconds_per_simulated_second = X
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
duration=1
while (($#)); do
  case "$1" in
    --duration) duration=$2; shift 2 ;;
    *) echo "usage: bench/tfdem-tsuji.sh [--duration SECONDS]" >&2; exit 2 ;;
  esac
done
gb=$(realpath -m "${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}")
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
core=$(($(nproc) - 1))

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$repo/configs/tsuji-jet-tfdem.json" "$work/bench.json" "$duration" <<'PY'
import json, sys
source, target, duration = sys.argv[1], sys.argv[2], float(sys.argv[3])
config = json.load(open(source))
params = config["stages"]["bed"]["params"]
params["settle_duration"] = "0.5 s"
params["duration"] = f"{duration} s"
params["average_from"] = "0 s"
params.pop("average_to", None)
params["frames"] = 0
params["progress"] = False
config["name"] = "bench-tfdem-tsuji"
json.dump(config, open(target, "w"), indent=1)
PY

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores; pinned to core $core"
echo "grainbridge: $("$gb" --version 2>/dev/null | head -1) ($(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?'))"
(cd "$work" && taskset -c "$core" "$gb" run bench.json > run.log 2>&1) || { cat "$work/run.log" >&2; exit 1; }
# The run phase's line: "bed: <gas steps> steps of <particle sub-steps> particles in <T> s: <rate> ..."
python3 - "$work/run.log" "$duration" <<'PY'
import re, sys
log, duration = open(sys.argv[1]).read(), float(sys.argv[2])
m = re.search(r"bed: (\d+) steps of (\d+) particles in ([0-9.]+) s: ([0-9.e+]+) particle-steps/s", log)
if not m:
    sys.exit("no run-phase timing line in the log:\n" + log)
steps, items, seconds = int(m.group(1)), int(m.group(2)), float(m.group(3))
print(f"simulated: {duration:g} s after 0.5 s of settling; {steps} gas steps of {items // 2400} DEM steps of 2400 beads")
print(f"particle-steps per second: {steps * items / seconds:.4g}")
print(f"gas steps per second: {steps / seconds:.4g}")
print(f"wall_seconds_per_simulated_second = {seconds / duration:.2f}")
PY
