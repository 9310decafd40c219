#!/usr/bin/env python3
"""The quickstart's shear states on both DEM engines give the same closure points (issue 32).

Runs configs/quickstart.json's shear and closures stages with the shear stage's `engine` swept
over grainbridge and lammps (one rank each), then compares every closure point of one engine with
the other's at the same solid fraction and restitution: for each quantity with an error bar,
z = (lammps - grainbridge) / sqrt(err_g^2 + err_l^2). The two engines equal each other to 1e-10
for the first few thousand steps (tests/workflows/DemLammpsEngineTest.cpp) and then part by chaos,
so their points are two samples of one steady state: z is a standard normal variable, up to the
error bars' own uncertainty (a block error from a few blocks is itself uncertain by tens of
per cent). Fails when the mean z^2 exceeds 2 (a systematic difference of one error bar on every
point gives 2) or any |z| exceeds 5. Prints the table. Label slow: about 5 minutes on 2 cores.
Exit 77 (skipped) when grainbridge was built without LAMMPS.
"""
import argparse
import csv
import json
import math
import pathlib
import subprocess
import sys

QUANTITIES = ["pressure", "shear_stress", "granular_temperature", "dissipation_rate", "coordination", "p_theta",
              "eta_theta", "j_theta"]
MEAN_Z2_LIMIT = 2.0
Z_LIMIT = 5.0


def closure_points(results):
    """{engine: {(solid fraction, restitution): {quantity: value}}} from the closures stage."""
    engine_of = {}
    for manifest_path in results.glob("shear/*/manifest.json"):
        manifest = json.loads(manifest_path.read_text())
        engine_of[manifest["key"]] = manifest["params"].get("engine", "grainbridge")
    points = {}
    for path in results.glob("closures/*/closure_point.csv"):
        manifest = json.loads((path.parent / "manifest.json").read_text())
        engine = engine_of[manifest["upstream"][0]]
        values = {row["quantity"]: float(row["value"]) for row in csv.DictReader(path.open())}
        key = (round(values["solid_fraction"], 2), round(values["restitution"], 2))
        points.setdefault(engine, {})[key] = values
    return points


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--grainbridge", required=True)
    parser.add_argument("--repo", required=True, type=pathlib.Path)
    parser.add_argument("--work", required=True, type=pathlib.Path)
    args = parser.parse_args()
    args.work.mkdir(parents=True, exist_ok=True)
    config = json.loads((args.repo / "configs" / "quickstart.json").read_text())
    shear = config["stages"]["shear"]
    shear["sweep"]["engine"] = ["grainbridge", "lammps"]
    config["name"] = "engines"
    config["stages"] = {name: config["stages"][name] for name in ("shear", "closures")}
    (args.work / "engines.json").write_text(json.dumps(config, indent=2))
    check = subprocess.run([args.grainbridge, "check", "engines.json"], cwd=args.work, capture_output=True, text=True)
    if "this build has no LAMMPS" in check.stderr + check.stdout or "install liblammps-dev" in check.stderr:
        print("skipped: grainbridge was built without LAMMPS")
        return 77
    subprocess.run([args.grainbridge, "run", "engines.json", "-q"], cwd=args.work, check=True)
    points = closure_points(args.work / "results" / "engines")
    ours, theirs = points["grainbridge"], points["lammps"]
    if sorted(ours) != sorted(theirs) or len(ours) != 6:
        print(f"expected the same 6 states on both engines, found {sorted(ours)} and {sorted(theirs)}")
        return 1
    z_values = []
    print("phi   e    " + "  ".join(f"{q[:16]:>16}" for q in QUANTITIES))
    for key in sorted(ours):
        cells = []
        for q in QUANTITIES:
            a, b = ours[key][q], theirs[key][q]
            error = math.hypot(ours[key][q + "_err"], theirs[key][q + "_err"])
            z = (b - a) / error
            z_values.append((z, key, q))
            cells.append(f"{100 * (b / a - 1):+6.1f}% ({z:+5.1f})")
        print(f"{key[0]:.2f}  {key[1]:.1f}  " + "  ".join(f"{c:>16}" for c in cells))
    mean_z2 = sum(z * z for z, _, _ in z_values) / len(z_values)
    worst = max(z_values, key=lambda t: abs(t[0]))
    within = sum(abs(z) < 2 for z, _, _ in z_values)
    print(f"lammps against grainbridge: mean z^2 = {mean_z2:.2f} over {len(z_values)} values, {within} within 2 sigma, "
          f"largest |z| = {abs(worst[0]):.2f} ({worst[2]} at solid fraction {worst[1][0]}, restitution {worst[1][1]})")
    if mean_z2 > MEAN_Z2_LIMIT or abs(worst[0]) > Z_LIMIT:
        print(f"FAIL: mean z^2 must be <= {MEAN_Z2_LIMIT} and every |z| <= {Z_LIMIT}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
