#!/usr/bin/env bash
# TF-DEM throughput of a shipped bed config (the shared body of bench/tfdem-tsuji.sh and
# bench/tfdem-goldschmidt.sh): its `bed` stage alone, settled for --settle seconds without the gas
# (not timed), then --duration simulated seconds with the gas (timed: the stage's own timing of
# its run phase), on one core, no frames. Prints particle-steps per second and gas steps per
# second, then the settling's own timing (the same bed's DEM without the gas: issue 59) and
# `tfdem_over_dem = X` (wall time per simulated second with the gas over without), and last the
# wall time per simulated second.
#
# Builds nothing: it uses build-release/bin/grainbridge (scripts/quickstart.sh builds it) or
# $GRAINBRIDGE.
#
# Usage: bench/tfdem-bed.sh CONFIG [--duration SECONDS] [--settle SECONDS]
# Last line: wall_seconds_per_simulated_second = X
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage="usage: bench/tfdem-bed.sh CONFIG [--duration SECONDS] [--settle SECONDS]"
(($#)) || { echo "$usage" >&2; exit 2; }
config=$(realpath "$1")
shift
duration=1
settle=0.5
while (($#)); do
  case "$1" in
    --duration) duration=$2; shift 2 ;;
    --settle) settle=$2; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
gb=$(realpath -m "${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}")
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
core=$(($(nproc) - 1))

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$config" "$work/bench.json" "$duration" "$settle" <<'PY'
import json, sys
source, target, duration, settle = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
config = json.load(open(source))
config["stages"] = {"bed": config["stages"]["bed"]}  # the bed alone: no extraction timed
params = config["stages"]["bed"]["params"]
params["settle_duration"] = f"{settle} s"
# A whole number of the config's output intervals (the stage refuses any other duration): the
# nearest to the one asked, written where the timing below reads it.
interval = float(params.get("output_interval", "0.01 s").split()[0])
duration = max(1, round(duration / interval)) * interval
params["duration"] = f"{duration:.12g} s"
open(target + ".duration", "w").write(f"{duration:.12g}")
params["average_from"] = "0 s"
params.pop("average_to", None)
params["frames"] = 0
params["progress"] = False
config["name"] = "bench-tfdem"
json.dump(config, open(target, "w"), indent=1)
PY

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores; pinned to core $core"
echo "grainbridge: $("$gb" --version 2>/dev/null | head -1) ($(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "config: $(realpath --relative-to="$repo" "$config"), settled ${settle} s (not timed)"
duration=$(cat "$work/bench.json.duration")
(cd "$work" && taskset -c "$core" "$gb" run bench.json > run.log 2>&1) || { cat "$work/run.log" >&2; exit 1; }
# The run phase's line: "bed: <DEM steps> DEM steps of <particles> particles in <T> s: <rate> ...",
# and the stage's "bed: gas step <s> s = <n> DEM steps".
python3 - "$work/run.log" "$duration" "$settle" <<'PY'
import re, sys
log, duration, settle = open(sys.argv[1]).read(), float(sys.argv[2]), float(sys.argv[3])
m = re.search(r"bed: (\d+) DEM steps of (\d+) particles in ([0-9.]+) s: ([0-9.e+]+) particle-steps/s, ([0-9.]+) gas iterations", log)
g = re.search(r"bed: gas step \S+ s = (\d+) DEM steps", log)
if not m or not g:
    sys.exit("no run-phase timing line in the log:\n" + log)
dem_steps, particles, seconds, iterations = int(m.group(1)), int(m.group(2)), float(m.group(3)), float(m.group(5))
substeps = int(g.group(1))
steps = dem_steps // substeps
print(f"simulated: {duration:g} s; {steps} gas steps of {substeps} DEM steps of {particles} particles; "
      f"{iterations:g} gas iterations per gas step")
print(f"particle-steps per second: {dem_steps * particles / seconds:.4g}")
print(f"gas steps per second: {steps / seconds:.4g}")
# The settling phase is the same bed's DEM without the gas: "bed: settling: <n> DEM steps of <p>
# particles in <T> s". A settled bed is packed, the run's fluidized: the contacts differ.
s = re.search(r"bed: settling: (\d+) DEM steps of (\d+) particles in ([0-9.]+) s", log)
if s and settle > 0:
    settle_seconds = float(s.group(3))
    print(f"DEM without the gas (the settling, {settle:g} s): {int(s.group(1)) * int(s.group(2)) / settle_seconds:.4g} "
          f"particle-steps per second, {settle_seconds / settle:.2f} wall s per simulated s")
    print(f"tfdem_over_dem = {(seconds / duration) / (settle_seconds / settle):.3f}")
print(f"wall_seconds_per_simulated_second = {seconds / duration:.2f}")
PY
