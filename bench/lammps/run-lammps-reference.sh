#!/usr/bin/env bash
# LAMMPS reference timing for the dense-bed DEM benchmark (the LAMMPS half of
# bench/dem-vs-lammps.sh). Inputs: ../shared/lammps-bench/in.box and in.timed.
#
#   1. Settles the 20,000-sphere bed once with in.box (n=25, nz=32, 40,000 steps) and writes it
#      with write_data. The file is cached (bench/lammps/.cache/ or --cache-dir) and reused.
#   2. Runs in.timed from that bed (10,000 steps, fresh contact history) --runs times on one
#      core: OMP_NUM_THREADS=1, no -sf suffix, pinned with taskset when it is available.
#   3. Prints per run the "Loop time", particle-steps/s = N_atoms * steps / loop time and the
#      contacts per particle, then the median; the last lines are machine-readable
#      `key = value` lines (lammps_loop_seconds, lammps_particle_steps_per_s, ...).
#
# Contacts per particle: measured with `compute contact/atom` (pairs with r < r_i + r_j; each
# contact counted at both of its particles; floor contacts not counted) averaged over all atoms
# at the last step of the timed run. The timed input is a copy of in.timed with those two
# computes and a thermo_style that reports them added before `run`; thermo output happens only
# at the first and last step, so the computes cost two evaluations in 10,000 steps. LAMMPS's
# "Ave neighs/atom" (half list, cutoff d + skin) is printed too, but it is not a contact count.
#
# Usage: bench/lammps/run-lammps-reference.sh [--runs N] [--datafile PATH] [--cache-dir DIR]
#          [--steps N] [--core CPU] [--lmp BINARY] [--n N] [--nz NZ] [--settle-only]
#   --datafile PATH  the settled bed to time from; if PATH does not exist it is settled there.
#                    Default: <cache-dir>/bed-n25-nz32-settle40000.data.
#   --runs N         timed runs (default 3).      --steps N   timed steps (default 10000).
#   --core CPU       CPU for taskset (default: the last one).
#   --n N --nz NZ    the bed's lattice: N x N x NZ spheres (default 25 x 25 x 32 = 20,000; the
#                    --scaling beds of bench/dem-vs-lammps.sh are 25 x 25 x 8 and 50 x 50 x 32).
#   --settle-only    settle (or find) the bed, print its path as lammps_datafile = PATH, stop.
# Environment: LAMMPS_BENCH_DIR (default: <repo>/../shared/lammps-bench).
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_dir=$(cd "$script_dir/../.." && pwd)
bench_inputs=${LAMMPS_BENCH_DIR:-$repo_dir/../shared/lammps-bench}

runs=3
steps=10000
datafile=""
cache_dir="$script_dir/.cache"
core=""
lmp=""
settle_only=0
# The bed every engine starts from: 25 x 25 x 32 = 20,000 spheres, settled 40,000 steps.
settle_n=25
settle_nz=32
settle_steps=40000

die() {
  echo "run-lammps-reference.sh: $*" >&2
  exit 1
}
need_value() { [[ $# -ge 2 && -n "$2" ]] || die "option $1 needs a value"; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) need_value "$@"; runs=$2; shift 2 ;;
    --steps) need_value "$@"; steps=$2; shift 2 ;;
    --datafile) need_value "$@"; datafile=$2; shift 2 ;;
    --cache-dir) need_value "$@"; cache_dir=$2; shift 2 ;;
    --core) need_value "$@"; core=$2; shift 2 ;;
    --lmp) need_value "$@"; lmp=$2; shift 2 ;;
    --n) need_value "$@"; settle_n=$2; shift 2 ;;
    --nz) need_value "$@"; settle_nz=$2; shift 2 ;;
    --settle-only) settle_only=1; shift ;;
    -h | --help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (try --help)" ;;
  esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || die "--runs must be a positive integer, got '$runs'"
[[ "$steps" =~ ^[1-9][0-9]*$ ]] || die "--steps must be a positive integer, got '$steps'"
[[ "$settle_n" =~ ^[1-9][0-9]*$ ]] || die "--n must be a positive integer, got '$settle_n'"
[[ "$settle_nz" =~ ^[1-9][0-9]*$ ]] || die "--nz must be a positive integer, got '$settle_nz'"
for f in in.box in.timed; do
  [[ -r "$bench_inputs/$f" ]] || die "cannot read $bench_inputs/$f (set LAMMPS_BENCH_DIR)"
done

# --- LAMMPS binary ----------------------------------------------------------------------------
# Debian's package (bookworm: 29 Sep 2021 update 2) installs /usr/bin/lmp with GRANULAR built in.
find_lmp() {
  local c
  for c in lmp lmp_serial lmp_mpi lmp_stable; do
    if command -v "$c" >/dev/null 2>&1; then
      command -v "$c"
      return 0
    fi
  done
  return 1
}
if [[ -z "$lmp" ]]; then
  if ! lmp=$(find_lmp); then
    if [[ $(id -u) -eq 0 ]]; then
      echo "installing Debian's lammps package" >&2
      DEBIAN_FRONTEND=noninteractive apt-get install -y lammps >&2 ||
        { apt-get update >&2 && DEBIAN_FRONTEND=noninteractive apt-get install -y lammps >&2; }
      lmp=$(find_lmp) || die "lammps installed but no lmp binary found"
    else
      die "LAMMPS is not installed; run as root: apt-get install -y lammps"
    fi
  fi
fi
ncpu=$(nproc)  # before OMP_NUM_THREADS is set: GNU nproc honours it
export OMP_NUM_THREADS=1
# Open MPI refuses to start as root unless told; lmp runs as a singleton (no mpirun) here.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Captured once: piping `lmp -h` into `grep -q` would trip pipefail with SIGPIPE.
lmp_help=$("$lmp" -h 2>/dev/null || true)
[[ "$lmp_help" == *gran/hooke/history* ]] || die "$lmp lacks the GRANULAR package (pair gran/hooke/history)"
lammps_version=$(sed -n 's/.*Simulator - //p' <<<"$lmp_help" | head -n1)

pin=()
if command -v taskset >/dev/null 2>&1; then
  [[ -n "$core" ]] || core=$((ncpu - 1))
  if taskset -c "$core" true 2>/dev/null; then
    pin=(taskset -c "$core")
  else
    echo "note: taskset -c $core failed; running unpinned" >&2
  fi
fi

work_dir=$(mktemp -d "${TMPDIR:-/tmp}/gb-lammps.XXXXXX")
trap 'rm -rf "$work_dir"' EXIT

# --- 1. settled bed -----------------------------------------------------------------------------
if [[ -z "$datafile" ]]; then
  datafile="$cache_dir/bed-n${settle_n}-nz${settle_nz}-settle${settle_steps}.data"
fi
if [[ -s "$datafile" ]]; then
  echo "settled bed: $datafile (cached)"
else
  mkdir -p "$(dirname "$datafile")"
  partial="$datafile.partial.$$"
  settle_log="$datafile.settle.log"
  echo "settling the bed ($((settle_n * settle_n * settle_nz)) spheres, $settle_steps steps) into $datafile"
  echo "  log: $settle_log (this takes minutes)"
  start=$(date +%s.%N)
  (cd "$work_dir" && "${pin[@]}" "$lmp" -in "$bench_inputs/in.box" -log "$settle_log" -screen none \
    -var n "$settle_n" -var nz "$settle_nz" -var nsettle "$settle_steps" -var nsteps 0 \
    -var write 1 -var datafile "$partial") || { rm -f "$partial"; die "settling failed, see $settle_log"; }
  end=$(date +%s.%N)
  # Written under a temporary name first, so an interrupted settle never leaves a cached bed.
  mv "$partial" "$datafile"
  settle_loop=$(awk '/^Loop time/ {print $4; exit}' "$settle_log")
  printf 'settle: wall %.1f s, loop time %s s\n' "$(echo "$end - $start" | bc -l)" "$settle_loop"
  echo "lammps_settle_loop_seconds = $settle_loop"
fi
if ((settle_only)); then
  echo "lammps_datafile = $datafile"
  exit 0
fi

# --- 2. timed runs ------------------------------------------------------------------------------
# A copy of in.timed with the contact count added just before its `run` line.
timed_input="$work_dir/in.timed.contacts"
awk '
  /^[[:space:]]*run[[:space:]]/ && !done {
    print "compute\t\tgb_cn all contact/atom"
    print "compute\t\tgb_z all reduce ave c_gb_cn"
    print "thermo_style\tcustom step atoms ke c_gb_z"
    print "thermo_modify\tnorm no"
    done = 1
  }
  { print }
  END { if (!done) exit 1 }' "$bench_inputs/in.timed" >"$timed_input" || die "no run line in in.timed"

# The timed logs are kept (overwritten by the next invocation) for a look at LAMMPS's breakdown.
log_dir="$cache_dir/last-timed-logs"
mkdir -p "$log_dir"
cp "$timed_input" "$log_dir/"
loops=()
rates=()
contacts=()
neighs=()
for ((r = 1; r <= runs; ++r)); do
  log="$log_dir/timed-$r.log"
  # Other work on the machine shows up in the timing: keep the load average with each run.
  load_before=$(cut -d' ' -f1 /proc/loadavg)
  (cd "$work_dir" && "${pin[@]}" "$lmp" -in "$timed_input" -log "$log" -screen none \
    -var datafile "$datafile" -var nsteps "$steps") || die "timed run $r failed, log: $log"
  # "Loop time of 123.4 on 1 procs for 10000 steps with 20000 atoms"
  read -r loop nsteps_run natoms < <(awk '/^Loop time of/ {print $4, $9, $12; exit}' "$log")
  [[ -n "${loop:-}" ]] || die "no 'Loop time' line in $log"
  # Last thermo row before "Loop time": the final step, whose last column is c_gb_z.
  z=$(awk '$1 == "Step" {hdr = 1; next} /^Loop time of/ {print last; exit} hdr && NF {last = $NF}' "$log")
  neigh=$(awk '/^Ave neighs\/atom/ {print $4; exit}' "$log")
  rate=$(echo "$natoms * $nsteps_run / $loop" | bc -l)
  loops+=("$loop")
  rates+=("$rate")
  contacts+=("$z")
  neighs+=("$neigh")
  printf 'run %d: loop time %s s, %d atoms x %d steps, %.4g particle-steps/s, %.3f contacts/particle,' \
    "$r" "$loop" "$natoms" "$nsteps_run" "$rate" "$z"
  printf ' %s ave neighs/atom; 1-min load average %s before, %s after\n' \
    "$neigh" "$load_before" "$(cut -d' ' -f1 /proc/loadavg)"
done

median() {
  printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {
    if (NR % 2) printf "%.6g\n", v[(NR + 1) / 2]; else printf "%.6g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

echo "machine: $(uname -srm), $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $ncpu CPUs," \
  "pinned: ${pin[*]:-no}"
echo "lammps: $lmp ($lammps_version), OMP_NUM_THREADS=1, no suffix"
echo "git: $(git -C "$repo_dir" rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo "contacts_per_particle: compute contact/atom (r < r_i + r_j, both ends counted, no wall" \
  "contacts), mean over atoms at the last step"
echo "logs: $log_dir"
echo "lammps_datafile = $datafile"
echo "lammps_atoms = $natoms"
echo "lammps_steps = $nsteps_run"
echo "lammps_runs = $runs"
for ((r = 0; r < runs; ++r)); do
  echo "lammps_run_$((r + 1))_loop_seconds = ${loops[r]}"
done
echo "lammps_loop_seconds = $(median "${loops[@]}")"
echo "lammps_particle_steps_per_s = $(median "${rates[@]}")"
echo "lammps_contacts_per_particle = $(median "${contacts[@]}")"
echo "lammps_ave_neighs_per_atom = $(median "${neighs[@]}")"
