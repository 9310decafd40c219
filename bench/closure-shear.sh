#!/usr/bin/env bash
# The closure loop's `shear` stage (configs/closure-loop.json: 8 Lees-Edwards boxes of 2,000
# frictionless grains, phi 0.01-0.5, 100 1/s, dt 1e-6 s), shortened to a fraction of its steps
# (2 % by default: 50,000 steps and 10 frames per box), timed box by box with two binaries
# alternating on one core, as issue 33 timed it (issue 59, item 3).
#
# Usage: bench/closure-shear.sh OLD_BINARY NEW_BINARY [--fraction F] [--rounds N] [--core C]
# Each round runs every box with OLD then NEW (NEW then OLD in odd rounds, so neither always
# runs on a warmer core); per box the median wall time of each binary over the rounds.
# Last line: `closure_shear_speedup = X`, the stage's summed medians, old time over new (the
# speed-up; issue 59 asks for at least 1.5 against 6a32662).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
(($# >= 2)) || { sed -n '2,12p' "${BASH_SOURCE[0]}" >&2; exit 2; }
old=$(realpath "$1"); new=$(realpath "$2"); shift 2
fraction=0.02 rounds=3 core=${BENCH_CORE:-0}
while (($#)); do
  case "$1" in
    --fraction) fraction=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --core) core=$2; shift 2 ;;
    *) echo "unknown argument $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d /tmp/closure-shear.XXXXXX)
# One config per box: the stage's parameters with box_hi set to one entry of its sweep, the
# duration and frames cut to the fraction (at least one frame), no checkpoints.
python3 - "$repo/configs/closure-loop.json" "$work" "$fraction" <<'PY'
import json, sys
config, work, fraction = sys.argv[1], sys.argv[2], float(sys.argv[3])
stage = json.load(open(config))["stages"]["shear"]
params = stage["params"]
seconds = float(params["duration"].split()[0]) * fraction
params["duration"] = f"{seconds:.6g} s"
params["frames"] = max(1, round(params["frames"] * fraction))
params["series_points"] = max(2, round(params["series_points"] * fraction))
params.pop("checkpoint_interval", None)
for k, box in enumerate(stage["sweep"]["box_hi"]):
    params["box_hi"] = box
    json.dump({"name": f"closure-shear-box{k}", "stages": {"shear": {"type": "dem", "params": params}}},
              open(f"{work}/box{k}.json", "w"), indent=1)
    print(f"box{k} {box[0]}")
PY
boxes=$(ls "$work"/box*.json | wc -l)
echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); core $core"
echo "old: $old ($("$old" --version 2>/dev/null | head -1))"
echo "new: $new ($("$new" --version 2>/dev/null | head -1))"
time_box() {  # time_box BINARY BOX: wall seconds of one run
  local dir="$work/run-$(basename "$1")-$2" start end
  mkdir -p "$dir"
  start=$(date +%s.%N)
  (cd "$dir" && OMP_NUM_THREADS=1 taskset -c "$core" "$1" run "$work/box$2.json" --force > run.log 2>&1) ||
    { cat "$dir/run.log" >&2; echo "box $2 failed with $1" >&2; exit 1; }
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}'
}
for ((r = 1; r <= rounds; r++)); do
  for ((b = 0; b < boxes; b++)); do
    if ((r % 2)); then
      o=$(time_box "$old" "$b"); n=$(time_box "$new" "$b")
    else
      n=$(time_box "$new" "$b"); o=$(time_box "$old" "$b")
    fi
    echo "$b $o $n" >> "$work/times"
    echo "round $r box $b: old $o s, new $n s"
  done
done
python3 - "$work/times" "$boxes" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
total_old = total_new = 0.0
for b in range(int(sys.argv[2])):
    o = statistics.median(float(r[1]) for r in rows if int(r[0]) == b)
    n = statistics.median(float(r[2]) for r in rows if int(r[0]) == b)
    total_old += o; total_new += n
    print(f"box {b}: old {o:.2f} s, new {n:.2f} s, old/new {o / n:.2f}")
print(f"stage: old {total_old:.2f} s, new {total_new:.2f} s")
print(f"closure_shear_speedup = {total_old / total_new:.2f}")
PY
