#!/usr/bin/env bash
# grainbridge's multi-fluid solver against OpenFOAM's twoPhaseEulerFoam (v1912, Debian package
# `openfoam`) on the same bed: grainbridge's Goldschmidt monodisperse bed (the `bed` stage of
# configs/goldschmidt-mono.json at 1.5 U_mf = 1.92 m/s, rotation model off, 15 x 45 cells,
# pseudo-2D), both at ONE fixed time step, one core each, one after the other, no field output.
# Prints both wall times and both mean bed heights (Eq. 5.22, time-averaged over the second half
# of the run) and, if the heights agree within 5 %, ends with
#   ratio grainbridge/openfoam = X
# X = grainbridge's wall seconds per simulated second / OpenFOAM's (below 1: grainbridge faster).
# Heights more than 5 % apart mean the two codes did not simulate the same bed: no ratio, exit 1.
#
# The OpenFOAM case is bench/openfoam-goldschmidt/; every model mapping is commented there
# (constant/turbulenceProperties.particles, phaseProperties, thermophysicalProperties.air,
# system/fvSchemes, fvSolution, 0/*) and summarised in the table this script prints. The
# mappings v1912 cannot make exact are listed under "not matched" in that table.
#
# Builds nothing: it uses build-release/bin/grainbridge (scripts/quickstart.sh builds it) or
# $GRAINBRIDGE. OpenFOAM: if twoPhaseEulerFoam is not on PATH, installs the Debian packages
# `openfoam openfoam-examples` when run as root, otherwise says so and exits 2.
#
# Usage: bench/mfm-vs-openfoam.sh [--duration SECONDS] [--dt SECONDS]
#   --duration  simulated time of each run (default 10; averages over the second half)
#   --dt        the fixed time step of both codes (default 2e-4 s: the largest of 2e-4, 5e-4 and
#               1e-3 s at which both ran 10 s; at 5e-4 s grainbridge stopped at t = 1.6 s (a step
#               that did not converge in 50 iterations), at 1e-3 s twoPhaseEulerFoam diverged)
# Exit: 0 with the ratio, 1 if a run failed or the heights differ by more than 5 %, 2 on usage
# or a missing program.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
case_template="$repo/bench/openfoam-goldschmidt"
duration=10
dt=2e-4
usage="usage: bench/mfm-vs-openfoam.sh [--duration SECONDS] [--dt SECONDS]"
while (($#)); do
  case "$1" in
    --duration) duration=$2; shift 2 ;;
    --dt) dt=$2; shift 2 ;;
    -h|--help) echo "$usage"; exit 0 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
python3 - "$duration" "$dt" <<'PY' || { echo "$usage" >&2; exit 2; }
import sys
duration, dt = float(sys.argv[1]), float(sys.argv[2])
steps = duration / dt
sample = 0.01 / dt
# Both codes sample the height every 0.01 s: dt must divide 0.01 s and the duration.
ok = duration > 0 and dt > 0 and abs(steps - round(steps)) < 1e-6 * steps and abs(sample - round(sample)) < 1e-6 \
     and duration >= 0.4
if not ok:
    print(f"--duration {duration:g} and --dt {dt:g}: dt must divide both 0.01 s and the duration (>= 0.4 s, so "
          f"that the second half holds 20 height samples)",
          file=sys.stderr)
    sys.exit(1)
PY

# The programs.
gb=$(realpath -m "${GRAINBRIDGE:-$repo/build-release/bin/grainbridge}")
[[ -x "$gb" ]] || { echo "no grainbridge binary at $gb: run scripts/quickstart.sh first (or set GRAINBRIDGE)" >&2; exit 2; }
if ! command -v twoPhaseEulerFoam > /dev/null; then
  if [[ $(id -u) -eq 0 ]] && command -v apt-get > /dev/null; then
    echo "twoPhaseEulerFoam is not on PATH: installing the Debian packages openfoam openfoam-examples" >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y openfoam openfoam-examples >&2 ||
      { apt-get update >&2 && DEBIAN_FRONTEND=noninteractive apt-get install -y openfoam openfoam-examples >&2; }
  else
    echo "twoPhaseEulerFoam is not on PATH: install OpenFOAM v1912 (Debian/Ubuntu: sudo apt-get install openfoam" \
      "openfoam-examples), or run this script as root to have it installed" >&2
    exit 2
  fi
fi
# The Debian build finds its etc/ (controlDict, cellModels) through WM_PROJECT_DIR.
if [[ -z ${WM_PROJECT_DIR:-} ]]; then
  for dir in /usr/share/openfoam /usr/lib/openfoam/openfoam*; do
    [[ -f $dir/etc/controlDict ]] && { export WM_PROJECT_DIR=$dir; break; }
  done
fi
for tool in twoPhaseEulerFoam blockMesh foamDictionary; do
  command -v "$tool" > /dev/null || { echo "OpenFOAM's $tool is not on PATH" >&2; exit 2; }
done
core=$(($(nproc) - 1))

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Outer iterations and tolerances of the two codes (stated, printed).
gb_tolerance=1e-4      # grainbridge: normalised residuals of a converged step (its default)
gb_max_iterations=50   # grainbridge: outer iterations before a step is retried (its default)
of_outer=3             # OpenFOAM: PIMPLE nOuterCorrectors per step, fixed (the tutorial's 3)

of_version=$(dpkg-query -W -f '${Version}' openfoam 2> /dev/null || true)
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores; each run pinned to core $core, one after the other"
echo "grainbridge: $("$gb" --version 2>/dev/null | head -1) ($(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "openfoam: twoPhaseEulerFoam $(command -v twoPhaseEulerFoam)${of_version:+, Debian package openfoam $of_version}"
cat <<EOF
bed: configs/goldschmidt-mono.json stage bed at 1.92 m/s, rotation off: 15 x 45 x 1 cells of 1 cm
  (15 x 45 x 1.5 cm), glass d 2.49 mm rho 2526 e 0.97, air 1.2 kg/m3 1.8e-5 Pa s; bed 0-15 cm at
  eps_s 0.583 (x (1 - 0.01 noise), the same mt19937_64 seed-1 noise in both), gas 3.0695 m/s in it
  and 1.28 above; simulated $duration s, mean height averaged over $(python3 -c "print(f'{$duration/2:g}-{$duration:g}')") s
time step: fixed dt = $dt s in both (grainbridge dt = dt_min = dt_max; OpenFOAM deltaT, adjustTimeStep no)
outer iterations: grainbridge until normalised residuals < $gb_tolerance, at most $gb_max_iterations per step
  (tolerance, max_iterations); OpenFOAM PIMPLE nOuterCorrectors $of_outer (fixed) x nCorrectors 1,
  linear solvers to absolute tolerances p_rgh 1e-8, alpha 1e-9, U/Theta/e 1e-6 (relTol 0)
model mapping (grainbridge -> OpenFOAM v1912; reasons in bench/openfoam-goldschmidt/):
  gas                  incompressible 1.2 kg/m3 -> rhoConst 1.2 (exact), laminar (exact)
  drag                 Syamlal-O'Brien C 0.8 D 2.65 -> SyamlalOBrien (hard-coded 0.8/2.65: exact), no swarm
  added mass, lift     none -> virtualMass none, lift none (exact)
  heat transfer        none (isothermal) -> RanzMarshall between equal temperatures (trivial)
  granular energy      PDE (Eq. 3.34) -> kineticTheory, equilibrium off
  g0                   Carnahan-Starling -> CarnahanStarling (exact)
  granular pressure    Lun -> Lun (exact); bulk viscosity Lun's (exact); dissipation Eq. 5.7 (exact)
  shear viscosity      Lun 1984 -> Gidaspow (= Lun with e -> 1 in two factors: +1.3..2.1 % at e 0.97)
  conductivity         Lun 1984 -> Gidaspow (= Lun with e -> 1 in kappa0: +6.2..7.9 % at e 0.97)
  plastic regime       1e24 (0.417 - eps_g)^10, Schaeffer 30 deg, mu_p <= 100 Pa s
                       -> Schaeffer phi 30, alphaMinFriction 0.583, maxNut 0.0396 m2/s (= 100 Pa s)
  walls (gas)          no slip -> noSlip (exact)
  walls (solids)       Johnson-Jackson phi' 0.6, e_w 0.97, eps_max 0.583 -> slip: partialSlip with JJ's
                       value fraction 0.75 (v1912's JohnsonJacksonParticleSlip leaks solids through the
                       wall: uninitialised refValue); theta: JohnsonJacksonParticleTheta 0.6, 0.97 with
                       kineticTheory alphaMax = 0.583/2526 (v1912 leaves rho_s out of that condition)
  outlet               101325 Pa, backflow gas only -> prghPressure; alpha inletOutlet 0 (exact)
  convection           superbee everywhere -> Gauss SuperBee / SuperBeeV (alpha by MULES)
  not matched          Ma-Ahmadi gas damping of Lun's mu and kappa (v1912 has none);
                       gas slip production of theta: Koch 81 eps mu_g^2 |u|^2/(g0 d^3 rho sqrt(pi theta))
                       -> Gidaspow beta^2 d |u|^2/(4 eps rho sqrt(pi theta));
                       plastic pressure eps_s P* -> P*; solids pressure enters OpenFOAM only as
                       pPrime grad(alpha) (no grad(theta) part); JJ slip's value fraction fixed at
                       0.75 (JJ's is 0.68-0.79 for eps_s 0.1-0.58); MULES caps alpha at 0.62
EOF

# ---- grainbridge --------------------------------------------------------------------------
# The shipped config's bed, one sweep point, the averaging window the last half of the run, the
# fixed step (dt = dt_min = dt_max) and the outer-iteration settings written out.
python3 - "$repo/configs/goldschmidt-mono.json" "$work/bench.json" "$duration" "$dt" "$gb_tolerance" \
  "$gb_max_iterations" <<'PY'
import json, sys
source, target = sys.argv[1], sys.argv[2]
duration, dt, tolerance, max_iterations = float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]), int(sys.argv[6])
config = json.load(open(source))
stage = config["stages"]["bed"]
stage.pop("sweep", None)
params = stage["params"]
params["boundaries"][0]["gas_inflow"] = "1.92 m/s"
params["rotation_model"] = False
params["duration"] = f"{duration} s"
params["average_from"] = f"{duration / 2} s"
params["frames"] = 0
params["progress"] = False
params["dt"] = params["dt_min"] = params["dt_max"] = f"{dt} s"
params["tolerance"] = tolerance
params["max_iterations"] = max_iterations
config["name"] = "bench-mfm-vs-openfoam"
config["stages"] = {"bed": stage}
json.dump(config, open(target, "w"), indent=1)
PY

echo "running grainbridge ..."
(cd "$work" && taskset -c "$core" "$gb" run bench.json > gb.log 2>&1) ||
  { tail -30 "$work/gb.log" >&2; echo "grainbridge failed at the fixed step $dt s (log above)" >&2; exit 1; }
gb_manifest=$(ls "$work"/results/bench-mfm-vs-openfoam/bed/*/manifest.json)

# ---- OpenFOAM -----------------------------------------------------------------------------
case_dir="$work/openfoam"
cp -r "$case_template" "$case_dir"
sample_steps=$(python3 -c "print(round(0.01 / $dt))")
foamDictionary -entry endTime -set "$duration" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry writeInterval -set "$duration" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry deltaT -set "$dt" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry functions.meanHeight.executeInterval -set "$sample_steps" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry functions.meanHeight.writeInterval -set "$sample_steps" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry functions.solidsInventory.executeInterval -set "$sample_steps" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry functions.solidsInventory.writeInterval -set "$sample_steps" "$case_dir/system/controlDict" > /dev/null
foamDictionary -entry PIMPLE.nOuterCorrectors -set "$of_outer" "$case_dir/system/fvSolution" > /dev/null
# grainbridge's initial state (engines/mfm/InitialRegions.cpp): for every cell, i fastest, one
# uniform draw of std::mt19937_64(seed 1); below y = 15 cm eps_s = 0.583 (1 - 0.01 draw), gas
# 3.0695 m/s up; above, no solids and gas 1.28 m/s. blockMesh numbers the cells i + 15 j too.
python3 - "$case_dir/0" <<'PY'
import re, sys
zero = sys.argv[1]
nx, ny = 15, 45

class MT19937_64:  # std::mt19937_64
    def __init__(self, seed):
        self.mt = [seed & (2**64 - 1)]
        for i in range(1, 312):
            p = self.mt[-1]
            self.mt.append((6364136223846793005 * (p ^ (p >> 62)) + i) & (2**64 - 1))
        self.i = 312
    def next(self):
        if self.i >= 312:
            mt = self.mt
            for k in range(312):
                y = (mt[k] & 0xFFFFFFFF80000000) | (mt[(k + 1) % 312] & 0x7FFFFFFF)
                mt[k] = mt[(k + 156) % 312] ^ (y >> 1) ^ (0xB5026F5AA96619E9 if y & 1 else 0)
            self.i = 0
        y = self.mt[self.i]
        self.i += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        return (y ^ (y >> 43)) & (2**64 - 1)
    def unit(self):  # std::uniform_real_distribution<double>(0, 1) of libstdc++
        return min(self.next() / 2.0**64, 1.0 - 2.0**-53)

rng = MT19937_64(1)
alpha, ugas, yc = [], [], []
for j in range(ny):
    for i in range(nx):
        y = (j + 0.5) * 0.01
        noise = rng.unit()
        bed = y < 0.15
        alpha.append(0.583 * (1.0 - 0.01 * noise) if bed else 0.0)
        ugas.append(3.0695 if bed else 1.28)
        yc.append(y)

def put(name, kind, values):
    path = f"{zero}/{name}"
    text = open(path).read()
    body = "\n".join(values)
    field = f"internalField   nonuniform List<{kind}>\n{len(values)}\n(\n{body}\n)\n;"
    text, n = re.subn(r"internalField\s+uniform[^;]*;", lambda m: field, text, count=1)
    assert n == 1, path
    open(path, "w").write(text)

put("alpha.particles", "scalar", [repr(a) for a in alpha])
put("alpha.air", "scalar", [repr(1.0 - a) for a in alpha])
put("U.air", "vector", [f"(0 {u!r} 0)" for u in ugas])
put("yc", "scalar", [repr(y) for y in yc])
PY
(cd "$case_dir" && blockMesh > log.blockMesh 2>&1) || { cat "$case_dir/log.blockMesh" >&2; exit 1; }
echo "running twoPhaseEulerFoam ..."
of_start=$(date +%s.%N)
(cd "$case_dir" && taskset -c "$core" twoPhaseEulerFoam > log.twoPhaseEulerFoam 2>&1) ||
  { tail -40 "$case_dir/log.twoPhaseEulerFoam" >&2; echo "twoPhaseEulerFoam failed at the fixed step $dt s (log above)" >&2; exit 1; }
of_end=$(date +%s.%N)
grep -q '^End' "$case_dir/log.twoPhaseEulerFoam" ||
  { tail -40 "$case_dir/log.twoPhaseEulerFoam" >&2; echo "twoPhaseEulerFoam did not finish (log above)" >&2; exit 1; }
of_series=$(ls "$case_dir"/postProcessing/meanHeight/0/volFieldValue*.dat | head -1)

# ---- comparison ---------------------------------------------------------------------------
python3 - "$gb_manifest" "$of_series" "$case_dir/log.twoPhaseEulerFoam" "$of_start" "$of_end" "$duration" "$dt" <<'PY'
import glob, json, math, os, sys
manifest, of_series, of_log = sys.argv[1], sys.argv[2], sys.argv[3]
of_start, of_end, duration, dt = float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6]), float(sys.argv[7])
half = duration / 2

def blocks(samples, n=10):
    """Mean and block error: n blocks of consecutive samples, sd of the block means / sqrt(n)."""
    size = len(samples) // n
    means = [sum(samples[b * size:(b + 1) * size]) / size for b in range(n)]
    mean = sum(samples) / len(samples)
    m = sum(means) / n
    return mean, math.sqrt(sum((x - m) ** 2 for x in means) / (n - 1) / n)

# grainbridge: the stage's summary (its own block averaging, Flyvbjerg-Petersen) and, for the
# same error estimate as OpenFOAM's, 10 blocks of its series' mean_height column.
m = json.load(open(manifest))
s = m["summary"]
gb_wall = float(m["timing"]["seconds"])
gb_h, gb_err = s["mean_height"], s["mean_height_err"]
gb_h10 = gb_err10 = None
series = glob.glob(os.path.join(os.path.dirname(manifest), "series.csv"))
if series:
    import csv
    rows = list(csv.DictReader(open(series[0])))
    col = next((c for c in ("mean_height_glass", "mean_height") if rows and c in rows[0]), None)
    tcol = next((c for c in ("time", "t") if rows and c in rows[0]), None)
    if col and tcol:
        window = [float(r[col]) for r in rows if float(r[tcol]) >= half - 1e-9]
        if len(window) >= 20:
            gb_h10, gb_err10 = blocks(window)
steps = s["solver_steps"]
change = s.get("solids_volume_change")
print(f"grainbridge: {steps} steps of {dt:g} s, {s['iterations_per_step']:.2f} outer iterations per step, "
      f"{s['retries']} retried" + (f"; solids inventory change {100 * change:+.2f} %" if change is not None else ""))
print(f"  wall {gb_wall:.1f} s, {gb_wall / duration:.2f} wall s per simulated s")
line = f"  mean particle height {gb_h:.4f} +- {gb_err:.4f} m (summary, blocking)"
if gb_h10 is not None:
    line += f"; 10 blocks: {gb_h10:.4f} +- {gb_err10:.4f} m"
print(line)

# OpenFOAM: the meanHeight function object's series (time, weightedVolAverage(yc)).
samples = []
for row in open(of_series):
    if row.startswith("#") or not row.strip():
        continue
    t, h = row.split()[:2]
    if float(t) >= half - 1e-9:
        samples.append(float(h))
if len(samples) < 20:
    sys.exit(f"OpenFOAM wrote only {len(samples)} height samples in {half:g}-{duration:g} s ({of_series})")
of_h, of_err = blocks(samples)
of_wall = of_end - of_start
clock = [l for l in open(of_log) if l.startswith("ExecutionTime")]
of_steps = sum(1 for l in open(of_log) if l.startswith("Time = "))
inventory = []
for path in glob.glob(os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(of_series))), "solidsInventory", "0",
                                   "volFieldValue*.dat"))[:1]:
    inventory = [float(r.split()[1]) for r in open(path) if r.strip() and not r.startswith("#")]
note = ""
if inventory:
    note = f"; solids inventory change {100 * (inventory[-1] / inventory[0] - 1):+.2f} % (first sample to last)"
print(f"openfoam: {of_steps} steps of {dt:g} s, {clock[-1].strip() if clock else ''}{note}")
print(f"  wall {of_wall:.1f} s, {of_wall / duration:.2f} wall s per simulated s")
print(f"  mean particle height {of_h:.4f} +- {of_err:.4f} m (10 blocks of {len(samples) // 10} samples)")

diff = abs(gb_h - of_h) / gb_h
print(f"relative height difference |grainbridge - openfoam| / grainbridge = {100 * diff:.1f} %")
if diff > 0.05:
    print(f"the mean heights differ by more than 5 % ({gb_h:.4f} against {of_h:.4f} m): the two runs are not the "
          f"same bed, so no speed ratio", file=sys.stderr)
    sys.exit(1)
# Solids that leave through the outlet lower a bed: say so when the inventories part.
of_change = inventory[-1] / inventory[0] - 1 if inventory else None
if of_change is not None and change is not None and abs(of_change - change) > 0.01:
    print(f"warning: the solids inventories changed by {100 * change:+.1f} % (grainbridge) and {100 * of_change:+.1f} % "
          f"(openfoam: solids thrown out through the outlet): the heights compare beds of different inventories")
print(f"ratio grainbridge/openfoam = {(gb_wall / duration) / (of_wall / duration):.3f}")
PY
