"""A 3D fluidized bed through the mfm stage, opened in ParaView (issue 29).

Run by pvpython (Debian: python3-paraview), which is Python with paraview.simple:

    pvpython mfm_bed_paraview.py --grainbridge <binary> --config mfm_bed3d.json --work <folder>

Runs the config (a 6 x 12 x 4 bed of Table 4.1's grains on BiCGSTAB, bubbling at 1.5 m/s, about
twice the drag's U_mf) with `grainbridge run`, then checks:
- the solids held: every series row's mass_grain equals the first to 1e-10 relative, and the
  summary's mass_balance_grain is within 1e-10 (no grain leaves, none is made or lost);
- the field frames in ParaView's XDMFReader, frame by frame: 6 x 12 x 4 cells over the box's
  bounds, the arrays a user colours by, ep_g + ep_s_grain = 1 in every cell, and the grain mass
  ParaView sees (sum of rho_s ep_s V) equal to the series' at that time to 1e-10, and its mean
  particle height (Eq. 5.22 from ParaView's cell centres) equal to the series' to 1e-9: so the
  frames carry the solver's fields, in the cells they belong to;
- the bed is fluidized: by the last frame solids stand above the initial bed top.
"""
import argparse
import csv
import glob
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

from paraview import servermanager
from paraview.simple import Delete, XDMFReader

CELLS = (6, 12, 4)
GRAIN_DENSITY = 1491.8
BED_TOP = 0.0508  # the initial region's top [m]
ARRAYS = ["ep_g", "p_g", "u_g", "ep_s_grain", "u_s_grain", "theta_grain"]

errors = []


def check(condition, message):
    if not condition:
        errors.append(message)
    return condition


def leaves(data):
    if data is None:
        return []
    if data.IsA("vtkMultiBlockDataSet"):
        out = []
        for b in range(data.GetNumberOfBlocks()):
            out.extend(leaves(data.GetBlock(b)))
        return out
    return [data]


def scalar(arrays, name):
    a = arrays.GetArray(name)
    return None if a is None else [a.GetValue(t) for t in range(a.GetNumberOfTuples())]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--grainbridge", required=True)
    ap.add_argument("--config", required=True)
    ap.add_argument("--work", required=True)
    args = ap.parse_args()
    args.grainbridge = os.path.abspath(args.grainbridge)

    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    shutil.copy(args.config, os.path.join(args.work, "bed.json"))
    run = subprocess.run([args.grainbridge, "run", "bed.json"], cwd=args.work, capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout + run.stderr)
        print(f"FAIL: grainbridge run exited {run.returncode}")
        return 1
    config = json.load(open(args.config))
    name = config["name"]
    (stage,) = config["stages"].keys()
    manifests = glob.glob(os.path.join(args.work, "results", name, stage, "*", "manifest.json"))
    if len(manifests) != 1:
        print(f"FAIL: expected one product of stage {stage}, found {manifests}")
        return 1
    product = os.path.dirname(manifests[0])
    summary = json.load(open(manifests[0]))["summary"]

    # The solids held, from the solver's own account.
    rows = list(csv.DictReader(open(os.path.join(product, "series.csv"))))
    held0 = float(rows[0]["mass_grain"])
    drift = max(abs(float(r["mass_grain"]) - held0) for r in rows) / held0
    check(drift <= 1e-10, f"series: mass_grain drifts by {drift:.3e} of the first row's")
    check(abs(summary["mass_balance_grain"]) <= 1e-10, f"summary: mass_balance_grain {summary['mass_balance_grain']}")
    check(summary["mass_out_grain"] == 0.0, f"summary: {summary['mass_out_grain']} kg of grain left the bed")
    held_at = {round(float(r["time"]), 9): float(r["mass_grain"]) for r in rows}
    height_at = {round(float(r["time"]), 9): float(r["mean_height_grain"]) for r in rows}

    # The frames, as ParaView reads them.
    xmf = os.path.join(product, "fields.xmf")
    times = [float(t.get("Value")) for t in ET.parse(xmf).getroot().iter("Time")]
    check(len(times) == config["stages"][stage]["params"]["frames"] + 1, f"fields.xmf: {len(times)} frames")
    lengths = [0.0762, 0.1524, 0.0508]
    cell_volume = lengths[0] * lengths[1] * lengths[2] / (CELLS[0] * CELLS[1] * CELLS[2])
    reader = XDMFReader(FileNames=[xmf])
    reader.UpdatePipelineInformation()
    check(list(reader.TimestepValues) == times, f"fields: time steps {list(reader.TimestepValues)}, expected {times}")
    top_solids = 0.0
    heights_checked = 0
    for t in times:
        reader.UpdatePipeline(t)
        blocks = leaves(servermanager.Fetch(reader))
        if not check(len(blocks) == 1, f"fields t={t}: {len(blocks)} datasets, expected 1"):
            continue
        g = blocks[0]
        n = CELLS[0] * CELLS[1] * CELLS[2]
        check(g.GetNumberOfCells() == n, f"fields t={t}: {g.GetNumberOfCells()} cells, expected {n}")
        bounds = list(g.GetBounds())
        want = [0.0, lengths[0], 0.0, lengths[1], 0.0, lengths[2]]
        check(all(abs(a - b) < 1e-12 for a, b in zip(bounds, want)), f"fields t={t}: bounds {bounds}, expected {want}")
        names = [g.GetCellData().GetArrayName(k) for k in range(g.GetCellData().GetNumberOfArrays())]
        check(names == ARRAYS, f"fields t={t}: cell arrays {names}, expected {ARRAYS}")
        ep_g = scalar(g.GetCellData(), "ep_g")
        ep_s = scalar(g.GetCellData(), "ep_s_grain")
        if ep_g is None or ep_s is None:
            continue
        worst = max(abs(a + b - 1.0) for a, b in zip(ep_g, ep_s))
        check(worst < 1e-12, f"fields t={t}: ep_g + ep_s_grain off 1 by {worst:.3e}")
        mass = GRAIN_DENSITY * cell_volume * sum(ep_s)
        held = held_at.get(round(t, 9), held0)  # t = 0 is before the first series row
        check(abs(mass - held) <= 1e-10 * held, f"fields t={t}: grain mass in ParaView {mass!r}, series {held!r}")
        centres_y = [sum(g.GetCell(k).GetBounds()[2:4]) / 2.0 for k in range(g.GetNumberOfCells())]
        height = sum(e * y for e, y in zip(ep_s, centres_y)) / sum(ep_s)
        if round(t, 9) in height_at:
            want_h = height_at[round(t, 9)]
            heights_checked += 1
            check(abs(height - want_h) <= 1e-9 * want_h, f"fields t={t}: mean height in ParaView {height!r}, series {want_h!r}")
        if t == times[-1]:
            for k in range(g.GetNumberOfCells()):
                lo_y = g.GetCell(k).GetBounds()[2]
                if lo_y >= BED_TOP - 1e-12:
                    top_solids += ep_s[k]
    check(heights_checked == len(times) - 1, f"fields: {heights_checked} frames at series times, expected {len(times) - 1}")
    check(top_solids > 0.05, f"fields t={times[-1]}: no solids above the initial bed top: the bed did not fluidize")
    Delete(reader)

    for e in errors:
        print("FAIL: " + e)
    if errors:
        return 1
    print(f"mfm_bed_paraview: {len(times)} frames of {CELLS} cells read in ParaView; grain held to {drift:.1e}, "
          f"balance {summary['mass_balance_grain']:.1e}; Eq. 5.22 heights as the series' at {heights_checked} frames; "
          f"solids above the initial bed top at the end: {top_solids:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
