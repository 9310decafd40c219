#!/usr/bin/env bash
# Multi-fluid throughput on the grain-chaff combine (issue 29's benchmark): configs/combine.json,
# 3D, 40 x 8 x 10 cells, grain and chaff fed and carried out, 1 s simulated (--duration), one
# core, no frames. Prints the solver's statistics, cell updates per second and, last, the wall
# time per simulated second. Target: X <= 120 (the 10 s run within 20 minutes on one core).
#
# Builds nothing: it uses build-release/bin/grainbridge (scripts/quickstart.sh builds it) or
# $GRAINBRIDGE.
#
# Usage: bench/mfm-combine.sh [--duration SECONDS]
# Last line: wall_seconds_per_simulated_second = X
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
duration=1
while (($#)); do
  case "$1" in
    --duration) duration=$2; shift 2 ;;
    *) echo "usage: bench/mfm-combine.sh [--duration SECONDS]" >&2; exit 2 ;;
  esac
done
gb=$(realpath -m "${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}")
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
core=$(($(nproc) - 1))

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$repo/configs/combine.json" "$work/bench.json" "$duration" <<'PY'
import json, sys
source, target, duration = sys.argv[1], sys.argv[2], float(sys.argv[3])
config = json.load(open(source))
params = config["stages"]["combine"]["params"]
params["duration"] = f"{duration} s"
params["average_from"] = f"{duration / 2} s"
params["frames"] = 0
params["progress"] = False
config["name"] = "bench-mfm-combine"
json.dump(config, open(target, "w"), indent=1)
PY

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores; pinned to core $core"
echo "grainbridge: $("$gb" --version 2>/dev/null | head -1) ($(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?'))"
start=$(date +%s.%N)
(cd "$work" && taskset -c "$core" "$gb" run bench.json > run.log 2>&1) || { cat "$work/run.log" >&2; exit 1; }
end=$(date +%s.%N)
manifest=$(ls "$work"/results/bench-mfm-combine/combine/*/manifest.json)
python3 - "$manifest" "$start" "$end" "$duration" <<'PY'
import json, sys
manifest, start, end, duration = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
m = json.load(open(manifest))
s = m["summary"]
wall = float(m.get("timing", {}).get("seconds", end - start))
cells = 40 * 8 * 10
steps = s["solver_steps"]
iterations = steps * s["iterations_per_step"]
print(f"simulated: {duration:g} s, solver steps {steps}, {s['iterations_per_step']:.2f} iterations per step, "
      f"{s['retries']} retried")
print("fed / out (kg): " + ", ".join(f"{p} {s['mass_in_' + p]:.4g} / {s['mass_out_' + p]:.4g}"
                                     for p in ("gas", "grain", "chaff")))
print("balances: " + ", ".join(f"{p} {s['mass_balance_' + p]:.1e}" for p in ("gas", "grain", "chaff")))
print(f"wall: {wall:.1f} s (stage); cell updates per second: {cells * steps / wall:.4g} "
      f"(x outer iterations: {cells * iterations / wall:.4g})")
print(f"wall_seconds_per_simulated_second = {wall / duration:.2f}")
PY
