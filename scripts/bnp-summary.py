#!/usr/bin/env python3
"""Brazil-nut figures over preparation seeds, from a finished configs/bnp-wall-friction.json run.

For each dem instance (pack, wall friction, seed) and the surface extract made from it:
  - cycles until the nut was first at the top, and until it settled there for good
    (VALIDATION.md: its top within 1 d0 of the local free surface, judged on packed-bed frames;
    the extract stage's surface_id0_* summary);
  - the nut's top above the vibrating floor in the packed-bed frames of the last 5 cycles, its
    centre height (mean over the last 5 cycles of series.csv's z_id0, lab frame) and the highest
    it reached, in small-grain diameters d0;
then the mean and range over seeds per (pack, wall friction).

Usage: scripts/bnp-summary.py results/bnp-wall-friction
Heights assume the nut is particle id 0 (track_ids: [0]) and the container's floor rests at z = 0.
"""
import csv
import glob
import json
import math
import os
import sys


def manifests(folder):
    for path in sorted(glob.glob(os.path.join(folder, "*", "manifest.json"))):
        if ".partial" in path:
            continue
        with open(path) as f:
            yield os.path.dirname(path), json.load(f)


def main(root):
    surfaces, verdicts = {}, {}
    for stage in sorted(glob.glob(os.path.join(root, "surface*"))):
        for folder, m in manifests(stage):
            surfaces[m["upstream"][0]] = m["summary"]
            with open(os.path.join(folder, "surface.csv")) as f:
                verdicts[m["upstream"][0]] = [(float(r["time"]), r["at_top"] == "1", float(r["top"]))
                                              for r in csv.DictReader(f) if r["judged"] == "1"]
    rows = []
    for stage in sorted(glob.glob(os.path.join(root, "pack*"))):
        for folder, m in manifests(stage):
            p = m["params"]
            d0 = min(s["diameter"] for s in p["species"])
            period = 1.0 / p["walls"][0]["vibration_frequency"]
            with open(os.path.join(folder, "series.csv")) as f:
                series = [(float(r["time"]), float(r["z_id0"])) for r in csv.DictReader(f)]
            end = series[-1][0]
            last = [z for t, z in series if t >= end - 5 * period]
            s = surfaces.get(m["key"], {})

            def cycles(key):
                v = s.get(key)
                return None if v is None else v / period

            # Of the packed-bed frames after the first one at the top, the share still at the top.
            judged = verdicts.get(m["key"], [])
            first = next((k for k, (_, top, _) in enumerate(judged) if top), None)
            after = judged[first:] if first is not None else []
            share = None if not after else 100.0 * sum(top for _, top, _ in after) / len(after)
            # The nut's top above the vibrating floor (A sin 2 pi f t) in the packed frames of the
            # last 5 cycles.
            wall = p["walls"][0]
            floor = lambda t: wall["vibration_amplitude"] * math.sin(2 * math.pi * wall["vibration_frequency"] * t)
            packed = [top - floor(t) for t, _, top in judged if t >= end - 5 * period]
            rows.append({
                "share_after": share,
                "pack": m["stage"], "mu_wall": m["sweep_point"].get("walls/1/mu"), "seed": m["sweep_point"].get("seed"),
                "first_top": cycles("surface_id0_first_at_top_time"),
                "settled_top": cycles("surface_id0_settled_at_top_time"),
                "last_gap_d0": s.get("surface_id0_last_gap_diameters"),
                "end_height_d0": sum(last) / len(last) / d0, "max_height_d0": max(z for _, z in series) / d0,
                "packed_top_d0": None if not packed else sum(packed) / len(packed) / d0,
                "cycles": end / period})

    def show(v, fmt="{:.1f}"):
        return "-" if v is None else fmt.format(v)

    print("| pack | mu_wall | seed | first at top (cycle) | at top afterwards (% of packed frames) "
          "| settled at top (cycle) | last gap (d0) | nut top above floor, packed frames of last 5 cycles (d0) "
          "| nut centre, mean of last 5 cycles (d0) | highest (d0) | cycles run |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (r["pack"], -r["mu_wall"], r["seed"])):
        print(f"| {r['pack']} | {r['mu_wall']} | {r['seed']} | {show(r['first_top'])} | {show(r['share_after'], '{:.0f}')} "
              f"| {show(r['settled_top'])} "
              f"| {show(r['last_gap_d0'])} | {show(r['packed_top_d0'])} | {show(r['end_height_d0'])} "
              f"| {show(r['max_height_d0'])} "
              f"| {show(r['cycles'], '{:.0f}')} |")
    print()
    print("| pack | mu_wall | seeds | first at top: mean [min, max] (cycle) | never at top "
          "| settled at top: mean [min, max] (cycle) | never settled "
          "| nut top above floor at end: mean [min, max] (d0) |")
    print("|---|---|---|---|---|---|---|---|")
    groups = {}
    for r in rows:
        groups.setdefault((r["pack"], r["mu_wall"]), []).append(r)
    for (pack, mu), rs in sorted(groups.items(), key=lambda g: (g[0][0], -g[0][1])):
        def spread(values):
            return "-" if not values else f"{sum(values) / len(values):.1f} [{min(values):.1f}, {max(values):.1f}]"

        first = [r["first_top"] for r in rs if r["first_top"] is not None]
        settled = [r["settled_top"] for r in rs if r["settled_top"] is not None]
        heights = [r["packed_top_d0"] for r in rs if r["packed_top_d0"] is not None]
        print(f"| {pack} | {mu} | {len(rs)} | {spread(first)} | {len(rs) - len(first)} | {spread(settled)} "
              f"| {len(rs) - len(settled)} | {spread(heights)} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
