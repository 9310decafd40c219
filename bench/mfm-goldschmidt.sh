#!/usr/bin/env bash
# Multi-fluid throughput on the Goldschmidt monodisperse bed (issue 18's benchmark): the `bed`
# stage of configs/goldschmidt-mono.json at 1.5 U_mf (1.92 m/s) without the rotation model,
# 15 x 45 cells, 10 s simulated, on one core, no frames. Prints the solver's statistics, cell
# updates per second (cells x solver steps / wall second; and x outer iterations) and, last,
# the wall time per simulated second. Target: <= 30 (MFiX 21.3.2 takes 31-48 on this kind of
# machine, VALIDATION.md / issue 18).
#
# Builds nothing: it uses build-release/bin/grainbridge (scripts/quickstart.sh builds it) or
# $GRAINBRIDGE.
#
# --bed binary runs configs/goldschmidt-binary.json's bed at 1.30 m/s instead (bench/mfm-binary.sh);
# --bed combine runs configs/combine.json as shipped (bench/mfm-combine.sh).
# --set KEY=VALUE sets one of the stage's params (repeatable; VALUE is JSON when it parses as
# JSON, a string otherwise), e.g. --set pressure_solver=petsc (bench/mfm-petsc.sh).
#
# Usage: bench/mfm-goldschmidt.sh [--duration SECONDS] [--bed mono|binary|combine] [--set KEY=VALUE]...
# Last line: wall_seconds_per_simulated_second = X
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
duration=10
bed=mono
settings=()
while (($#)); do
  case "$1" in
    --duration) duration=$2; shift 2 ;;
    --bed) bed=$2; shift 2 ;;
    --set) settings+=("$2"); shift 2 ;;
    *) echo "usage: bench/mfm-goldschmidt.sh [--duration SECONDS] [--bed mono|binary|combine] [--set KEY=VALUE]..." >&2; exit 2 ;;
  esac
done
case "$bed" in
  mono) config=goldschmidt-mono; inflow="1.92 m/s" ;;
  binary) config=goldschmidt-binary; inflow="1.30 m/s" ;;
  combine) config=combine; inflow="" ;;
  *) echo "--bed: mono, binary or combine, not $bed" >&2; exit 2 ;;
esac
gb=$(realpath -m "${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}")
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
core=${BENCH_CORE:-$(($(nproc) - 1))}  # the last core unless BENCH_CORE names one

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The shipped config's bed (its mfm stage), one sweep point, the averaging window the last half of
# the run; the Goldschmidt beds at the inflow above without rotation.
python3 - "$repo/configs/$config.json" "$work/bench.json" "$duration" "$inflow" ${settings[@]+"${settings[@]}"} <<'PY'
import json, sys
source, target, duration, inflow = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
settings = sys.argv[5:]
config = json.load(open(source))
stage = next(s for s in config["stages"].values() if s["type"] == "mfm")
stage.pop("sweep", None)
params = stage["params"]
if inflow:
    params["boundaries"][0]["gas_inflow"] = inflow
    params["rotation_model"] = False
params["duration"] = f"{duration} s"
params["average_from"] = f"{duration / 2} s"
params["frames"] = 0
params["progress"] = False
for setting in settings:
    key, _, value = setting.partition("=")
    try:
        params[key] = json.loads(value)
    except ValueError:
        params[key] = value
config["name"] = "bench-mfm-goldschmidt"
config["stages"] = {"bed": stage}
json.dump(config, open(target, "w"), indent=1)
PY

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores; pinned to core $core"
echo "grainbridge: $("$gb" --version 2>/dev/null | head -1) ($(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?'))"
start=$(date +%s.%N)
(cd "$work" && taskset -c "$core" "$gb" run bench.json > run.log 2>&1) || { cat "$work/run.log" >&2; exit 1; }
end=$(date +%s.%N)
manifest=$(ls "$work"/results/bench-mfm-goldschmidt/bed/*/manifest.json)
python3 - "$manifest" "$start" "$end" "$duration" <<'PY'
import json, sys
manifest, start, end, duration = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
m = json.load(open(manifest))
s = m["summary"]
wall = float(m.get("timing", {}).get("seconds", end - start))
cells = 1
for n in m.get("params", {}).get("cells", [15, 45, 1]):
    cells *= n
steps = s["solver_steps"]
iterations = steps * s["iterations_per_step"]
print(f"simulated: {duration:g} s, solver steps {steps}, {s['iterations_per_step']:.2f} iterations per step, "
      f"{s['retries']} retried")
print(f"mean particle height (averaged over {duration / 2:g}-{duration:g} s): {s['mean_height']:.4f} +- "
      f"{s['mean_height_err']:.4f} m" + (f"; pressure drop {s['pressure_drop']:.0f} +- {s['pressure_drop_err']:.0f} Pa"
                                         if "pressure_drop" in s else ""))
phases = [k[len("mass_balance_"):] for k in s if k.startswith("mass_balance_")]
if any(s["mass_in_" + p] > 0 for p in phases if p != "gas"):
    print("fed / out (kg): " + ", ".join(f"{p} {s['mass_in_' + p]:.4g} / {s['mass_out_' + p]:.4g}" for p in phases))
    print("balances: " + ", ".join(f"{p} {s['mass_balance_' + p]:.1e}" for p in phases))
if "segregation_percentage" in s:
    print(f"segregation percentage: {s['segregation_percentage']:.1f} +- {s['segregation_percentage_err']:.1f} %")
print(f"wall: {wall:.1f} s (stage); cell updates per second: {cells * steps / wall:.4g} "
      f"(x outer iterations: {cells * iterations / wall:.4g})")
print(f"wall_seconds_per_simulated_second = {wall / duration:.2f}")
PY
