#!/usr/bin/env python3
"""What decides a binary bed's segregation, per run and per arm (issue 55), from finished mfm runs.

Reads every results/<workflow>/<stage>/<key>/ of the given results folders that holds a binary
bed's series.csv (segregation_percentage) and prints, per run (its sweep point), the averaging
window's means of s_p, each phase's theta and Eq. 5.22 height and the share of solids in packed
cells (series.csv columns theta_<phase>, mean_height_<phase>, plastic_solids_share), the 1 s block
means of s_p over 0-10 s (the rate), then per arm (the runs that differ only in `seed`) the mean
over realisations with its standard error. s_p in percent: mfm runs before impl 14 wrote Eq. 5.23's
fraction, which is read as 100 times that.

Usage: scripts/binary-bed-summary.py RESULTS_DIR [RESULTS_DIR ...] [--markdown]
"""
import csv
import glob
import json
import math
import os
import sys


def read_series(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def window_mean(series, column, start, end):
    values = [v for t, v in zip(series["time"], series[column]) if start - 1e-9 <= t <= end + 1e-9]
    return sum(values) / len(values) if values else math.nan


def blocks(series, column, end, width=1.0):
    out = []
    t0 = 0.0
    while t0 < end - 1e-9:
        out.append(window_mean(series, column, t0 + 1e-6, t0 + width))
        t0 += width
    return out


def runs_in(folder):
    for manifest in sorted(glob.glob(os.path.join(folder, "**", "manifest.json"), recursive=True)):
        run = os.path.dirname(manifest)
        series_csv = os.path.join(run, "series.csv")
        if not os.path.exists(series_csv):
            continue
        m = json.load(open(manifest))
        series = read_series(series_csv)
        if "segregation_percentage" not in series:
            continue
        if m.get("stage_type") == "mfm" and m.get("impl_version", 14) < 14:  # Eq. 5.23's fraction then
            series["segregation_percentage"] = [100.0 * v for v in series["segregation_percentage"]]
        yield run, m, series


def profile_ratios(path, phases):  # phases: [small, large]
    """(large/small in the lowest 2 cm, small/large in the top 2 cm of the bed), by solids volume:
    the bed's top is the highest height where the two phases together exceed 0.05."""
    if not os.path.exists(path) or None in phases:
        return None
    with open(path) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    small, large = (f"ep_s_{ph}" for ph in phases)
    bed = [r for r in rows if r[small] + r[large] > 0.05]
    if not bed:
        return None
    top = max(r["height"] for r in bed)
    low = [r for r in rows if r["height"] < 0.02]
    high = [r for r in bed if r["height"] > top - 0.02 + 1e-9]  # the cells whose centres lie in the top 2 cm
    ratio = lambda rs, a, b: sum(r[a] for r in rs) / max(sum(r[b] for r in rs), 1e-300)
    return ratio(low, large, small), ratio(high, small, large)


def mean_se(values):
    values = [v for v in values if not math.isnan(v)]
    n = len(values)
    if n == 0:
        return math.nan, math.nan, 0
    mean = sum(values) / n
    if n == 1:
        return mean, math.nan, 1
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    return mean, sd / math.sqrt(n), n


def main(argv):
    markdown = "--markdown" in argv
    folders = [a for a in argv if a != "--markdown"]
    if not folders:
        sys.exit(__doc__)
    arms = {}
    for folder in folders:
        for run, m, series in runs_in(folder):
            p = m["params"]
            start = float(p.get("average_from", 10.0))
            end = float(p.get("duration", 20.0))
            phases = [s["name"] for s in p["solids"]]
            point = {k.split("/")[-1]: v for k, v in m.get("sweep_written", {}).items()}
            seed = point.pop("seed", p.get("seed", 1))
            workflow = m.get("workflow")
            workflow = workflow.get("name", "") if isinstance(workflow, dict) else str(workflow)
            arm = f"{workflow}: " + ", ".join(f"{k} {v}" for k, v in sorted(point.items()))
            row = {"s_p (%)": window_mean(series, "segregation_percentage", start, end),
                   "plastic share": window_mean(series, "plastic_solids_share", start, end)
                   if "plastic_solids_share" in series else math.nan}
            for ph in phases:
                row[f"h_{ph} (m)"] = window_mean(series, f"mean_height_{ph}", start, end)
                if f"theta_{ph}" in series:
                    row[f"theta_{ph} (m2/s2)"] = window_mean(series, f"theta_{ph}", start, end)
            # Statement (c) of the reference (line 1257): more large than small solids in the lowest
            # 2 cm, more small at the bed top, from the window's profiles (profiles.csv).
            roles = p.get("segregation", {})
            lows = profile_ratios(os.path.join(run, "profiles.csv"), [roles.get("small"), roles.get("large")])
            if lows:
                row["large/small, lowest 2 cm"], row["small/large, top 2 cm"] = lows
            rate = blocks(series, "segregation_percentage", min(10.0, series["time"][-1]))
            row["retries"] = m["summary"].get("retries", math.nan)
            row["reached (s)"] = series["time"][-1]
            arms.setdefault(arm, []).append((seed, row, rate))
    for arm, runs in sorted(arms.items()):
        print(("### " if markdown else "== ") + arm)
        keys = list(runs[0][1].keys())
        if markdown:
            print("| seed | " + " | ".join(keys) + " |")
            print("|---" * (len(keys) + 1) + "|")
        for seed, row, rate in sorted(runs, key=lambda r: str(r[0])):
            cells = [f"{row[k]:.4g}" for k in keys]
            print(("| " if markdown else "") + f"{seed}" + (" | " if markdown else "  ") +
                  (" | " if markdown else "  ").join(cells) + (" |" if markdown else ""))
            print(("  " if not markdown else "") + "s_p 1 s blocks 0-10 s (%): " + " ".join(f"{v:.1f}" for v in rate)
                  + ("\n" if markdown else ""))
        for k in keys:
            mean, se, n = mean_se([row[k] for _, row, _ in runs])
            print(f"  {k}: {mean:.4g} +- {se:.2g} (standard error over {n} realisations)")
        print()


if __name__ == "__main__":
    main(sys.argv[1:])
