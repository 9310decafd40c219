#!/usr/bin/env python3
"""Kinetic theory against DEM over the simple-shear sweep, from a finished configs/shear-closures.json run.

Reads the compare stage's comparison.csv (DEM value, its block-averaging error, the model's
prediction at the same state and the relative deviation (DEM - model)/model) and prints, per
model and per side of friction, one Markdown table per quantity: rows are solid fraction,
columns restitution, cells the deviation in per cent. Quantities are the shear-scaled forms of
VALIDATION.md (p* = p/(rho_p d^2 gammadot^2), tau*, T* = T/(d gammadot)^2) and the
temperature-scaled forms a continuum engine reads (p/(rho_p theta), mu/(rho_p d sqrt(theta)),
J d/(rho_p theta^1.5)).

Then the energy balance of every state from the closure database beside the CSV
(results/<workflow>/grainbridge.sqlite): the power the contacts' dashpots dissipate over the work
done by the shear, tau_xy gammadot, with its block-averaging error. For frictionless grains it is
1 in a steady state (VALIDATION.md); with friction the dashpots miss the sliding losses, which is
why the closure's J is the shear work (extract impl_version 4).

Then the states VALIDATION.md asserts (solid fraction <= 0.2, e = 0.9, frictionless) with the
largest |deviation| against the 15 % tolerance, for lun1984.

Usage: scripts/shear-summary.py results/shear-closures [--model lun1984] [--values]
  --values  also print DEM +- error and prediction per state (long form).
"""
import argparse
import csv
import glob
import json
import math
import os
import sqlite3
import sys

QUANTITIES = [
    ("p_shear", "p*"),
    ("tau_shear", "tau*"),
    ("t_shear", "T*"),
    ("p_theta", "p/(rho_p theta)"),
    ("eta_theta", "mu/(rho_p d sqrt(theta))"),
    ("j_theta", "J d/(rho_p theta^1.5)"),
]
ASSERTED = ("p_shear", "tau_shear", "t_shear")
TOLERANCE = 0.15


def comparison_rows(root):
    paths = [p for p in glob.glob(os.path.join(root, "*", "*", "comparison.csv")) if ".partial" not in p]
    if not paths:
        sys.exit(f"no comparison.csv under {root}/<compare stage>/<instance>/: has the compare stage run?")
    rows = {}
    for path in sorted(paths, key=os.path.getmtime):
        with open(path) as f:
            for r in csv.DictReader(f):
                # Solid fraction as set (the box edge is rounded to 0.1 um, so 0.04999986 is 0.05).
                key = (round(float(r["solid_fraction"]), 3), float(r["restitution"]), float(r["friction"]),
                       r["quantity"], r["model"])
                rows[key] = r  # the newest compare instance wins
    return rows


def energy_balance(database):
    con = sqlite3.connect(f"file:{database}?mode=ro", uri=True)
    points = con.execute(
        "SELECT solid_fraction, restitution, friction, shear_stress, shear_stress_err, shear_rate,"
        " dissipation_rate, dissipation_rate_err, extra_json FROM closure_points WHERE family = 'simple_shear'"
        " ORDER BY id").fetchall()
    # The newest point of each state: a rerun extract (new impl_version) leaves the older row.
    newest = {(round(p[0], 3), p[1], p[2]): p for p in points}
    points = [newest[k] for k in sorted(newest, key=lambda k: (k[2], k[0], k[1]))]
    if not points:
        return
    print("### Energy balance: contact dashpot dissipation over the shear work tau_xy gammadot\n")
    print("| friction | solid fraction | e | dashpots / shear work | error |")
    print("|---|---|---|---|---|")
    worst = {}
    for phi, e, mu, tau, tau_err, rate, j, j_err, extra in points:
        extra = json.loads(extra or "{}")
        if "dissipation_rate_dashpots" in extra:  # extract impl_version >= 4
            j, j_err = extra["dissipation_rate_dashpots"], extra["dissipation_rate_dashpots_err"]
        work = tau * rate
        if not work:
            continue
        ratio = j / work
        error = abs(ratio) * math.hypot(tau_err / tau, j_err / j if j else 0.0)
        worst[mu] = max(worst.get(mu, 0.0), abs(ratio - 1.0))
        print(f"| {mu:g} | {phi:.3g} | {e:g} | {ratio:.4f} | {error:.4f} |")
    print()
    for mu, w in sorted(worst.items()):
        print(f"friction {mu:g}: largest |dashpots / shear work - 1| = {100 * w:.1f} %")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root")
    parser.add_argument("--model", default="lun1984")
    parser.add_argument("--values", action="store_true")
    args = parser.parse_args()

    rows = {k: r for k, r in comparison_rows(args.root).items() if k[4] == args.model}
    if not rows:
        sys.exit(f"no rows for model {args.model}")
    fractions = sorted({k[0] for k in rows})
    restitutions = sorted({k[1] for k in rows})
    frictions = sorted({k[2] for k in rows})
    states = len({k[:3] for k in rows})
    print(f"{states} states against {args.model}; cells are (DEM - model)/model in %\n")

    for mu in frictions:
        for quantity, label in QUANTITIES:
            print(f"### {label}, friction {mu:g}\n")
            print("| solid fraction | " + " | ".join(f"e = {e:g}" for e in restitutions) + " |")
            print("|---|" + "---|" * len(restitutions))
            for phi in fractions:
                cells = []
                for e in restitutions:
                    r = rows.get((phi, e, mu, quantity, args.model))
                    cells.append(f"{100 * float(r['deviation']):+.1f}" if r else "-")
                print(f"| {phi:g} | " + " | ".join(cells) + " |")
            print()

    if args.values:
        print("| friction | solid fraction | e | quantity | DEM | DEM error | model | deviation |")
        print("|---|---|---|---|---|---|---|---|")
        for key in sorted(rows):
            r = rows[key]
            print(f"| {key[2]:g} | {key[0]:g} | {key[1]:g} | {key[3]} | {float(r['dem']):.4g} | "
                  f"{float(r['dem_err']):.2g} | {float(r['prediction']):.4g} | "
                  f"{100 * float(r['deviation']):+.1f} % |")
        print()

    database = os.path.join(args.root, "grainbridge.sqlite")
    if os.path.exists(database):
        energy_balance(database)

    asserted = [r for k, r in rows.items() if k[0] <= 0.2 and k[1] == 0.9 and k[2] == 0 and k[3] in ASSERTED]
    if asserted and args.model == "lun1984":
        worst = max(asserted, key=lambda r: abs(float(r["deviation"])))
        verdict = "within" if abs(float(worst["deviation"])) <= TOLERANCE else "OUTSIDE"
        print(f"asserted states (solid fraction <= 0.2, e = 0.9, frictionless): {len(asserted)} figures, "
              f"largest |deviation| {100 * abs(float(worst['deviation'])):.1f} % "
              f"({worst['quantity']} at solid fraction {float(worst['solid_fraction']):.3g}), "
              f"{verdict} the {100 * TOLERANCE:.0f} % of VALIDATION.md")


if __name__ == "__main__":
    main()
