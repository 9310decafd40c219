#!/usr/bin/env python3
"""LAMMPS and grainbridge step by step on LAMMPS's chute benchmark (issue 13).

Runs ../shared/lammps-bench/in.chute on its data.chute with thermo every step
(`thermo_modify format float %.15g`), then `grainbridge run configs/lammps-chute.json`, which
reads the same data file and runs the same 100 steps twice: with LAMMPS's tangential history
(`lammps_history`) and with the reference's Eq. 6.4 (`history`). Per step it compares the total
translational kinetic energy (LAMMPS `ke`) and rotational kinetic energy (`c_1`,
erotate/sphere) with grainbridge's series.csv.

Fails unless the compatible mode agrees to 1e-7 relative at every step; prints the default's
difference beside it. The config's stage chute_on_lammps runs the same 100 steps on engine lammps
(LAMMPS through its library, issue 32), which must equal engine grainbridge with lammps_history to
1e-10 relative in both energies at every step. Exit 77 (skipped) when ../shared/lammps-bench is not
there.
"""
import argparse
import csv
import json
import math
import pathlib
import re
import subprocess
import sys

TOLERANCE = 1e-7
ENGINE_TOLERANCE = 1e-10


def lammps_thermo(lmp, inputs, data, work, steps):
    script = (inputs / "in.chute").read_text()
    script = re.sub(r"^thermo\s+\d+\s*$", "thermo\t\t1\nthermo_modify\tformat float %.15g", script, flags=re.M)
    (work / "in.chute").write_text(script)
    subprocess.run([lmp, "-in", "in.chute", "-var", "datafile", str(data), "-var", "nsteps", str(steps),
                    "-log", "log.lammps", "-screen", "none"], cwd=work, check=True,
                   env={"OMP_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
    rows = {}
    header = None
    for line in (work / "log.lammps").read_text().splitlines():
        fields = line.split()
        if fields[:2] == ["Step", "Atoms"]:
            header = fields
            continue
        if header and len(fields) == len(header) and fields[0].isdigit():
            row = dict(zip(header, fields))
            rows[int(row["Step"])] = (float(row["KinEng"]), float(row["c_1"]))
        elif header and fields[:1] == ["Loop"]:
            header = None
    return rows


def grainbridge_series(gb, repo, work):
    subprocess.run([gb, "run", str(repo / "configs" / "lammps-chute.json"), "--workdir", str(work), "--force", "-q"],
                   cwd=repo, check=True)
    series = {}
    for csv_path in sorted(work.glob("results/**/series.csv")):
        manifest = json.loads((csv_path.parent / "manifest.json").read_text())
        mode = manifest["params"]["tangential_model"]
        if manifest["params"].get("engine", "grainbridge") == "lammps":
            mode = "engine lammps"
        with csv_path.open() as f:
            series[mode] = list(csv.DictReader(f))
    return series


def kinetic_energies(table):
    return {int(r["step"]): (float(r["ke_translational"]), float(r["ke_rotational"])) for r in table}


def count_atoms_of_type(data, atom_type):
    lines = data.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip().startswith("Atoms"))
    count = 0
    for line in lines[start + 1:]:
        fields = line.split()
        if not fields:
            if count:
                break
            continue
        if not fields[0].isdigit():
            break
        count += int(fields[1]) == atom_type
    return count


def compare(lmp_rows, gb_rows, steps):
    worst = [0.0, 0.0]
    where = [0, 0]
    first = None
    for step in range(1, steps + 1):  # series.csv starts after the first step
        if step not in lmp_rows or step not in gb_rows:
            raise SystemExit(f"step {step} missing (LAMMPS has it: {step in lmp_rows}, grainbridge: {step in gb_rows})")
        for k in range(2):
            rel = abs(gb_rows[step][k] - lmp_rows[step][k]) / abs(lmp_rows[step][k])
            if step == 1 and k == 0:
                first = (gb_rows[step][0] - lmp_rows[step][0], rel)
            if rel > worst[k]:
                worst[k], where[k] = rel, step
    return worst, where, first


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--grainbridge", required=True)
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--repo", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--steps", type=int, default=100)
    args = ap.parse_args()
    repo = pathlib.Path(args.repo).resolve()
    inputs = repo.parent / "shared" / "lammps-bench"
    data = inputs / "data.chute"
    if not data.is_file():
        print(f"{data} is missing (CI has ../shared beside the clone): skipped")
        return 77
    if not args.lmp or not pathlib.Path(args.lmp).exists():
        print("no LAMMPS binary (Debian package lammps; scripts/install-deps.sh installs it)")
        return 1
    work = pathlib.Path(args.work)
    (work / "lammps").mkdir(parents=True, exist_ok=True)
    lmp_rows = lammps_thermo(args.lmp, inputs, data, work / "lammps", args.steps)
    series = grainbridge_series(args.grainbridge, repo, work / "grainbridge")
    ok = True
    # Coordination counts the mobile grains (type 1; the frozen base is type 2), read from a file
    # whose species declare no counts.
    mobile = count_atoms_of_type(data, 1)
    for row in series.get("lammps_history", []):
        contacts, coordination = int(row["contacts"]), float(row["coordination"])
        if abs(coordination - 2.0 * contacts / mobile) > 1e-12 * coordination or coordination <= 0.0:
            print(f"FAIL: coordination {coordination} with {contacts} contacts and {mobile} mobile grains")
            ok = False
            break
    for mode in ("lammps_history", "history"):
        if mode not in series:
            print(f"no grainbridge run with tangential_model {mode}")
            return 1
        worst, where, first = compare(lmp_rows, kinetic_energies(series[mode]), args.steps)
        print(f"tangential_model {mode}: after step 1 the translational KE is {first[0]:+.6g} "
              f"({first[1]:.3g} relative) off LAMMPS; over {args.steps} steps the largest relative difference "
              f"is {worst[0]:.3g} (step {where[0]}) in translational and {worst[1]:.3g} (step {where[1]}) in "
              f"rotational kinetic energy")
        if mode == "lammps_history" and max(worst) > TOLERANCE:
            print(f"FAIL: the LAMMPS-compatible mode must agree to {TOLERANCE:g} relative at every step")
            ok = False
    if "engine lammps" not in series:
        print("no run of stage chute_on_lammps (engine lammps)")
        return 1
    worst, where, _ = compare({int(r["step"]): (float(r["ke_translational"]), float(r["ke_rotational"]))
                               for r in series["lammps_history"]}, kinetic_energies(series["engine lammps"]), args.steps)
    print(f"engine lammps against engine grainbridge (lammps_history): over {args.steps} steps the largest relative "
          f"difference is {worst[0]:.3g} (step {where[0]}) in translational and {worst[1]:.3g} (step {where[1]}) in "
          f"rotational kinetic energy")
    if max(worst) > ENGINE_TOLERANCE:
        print(f"FAIL: the two engines must agree to {ENGINE_TOLERANCE:g} relative at every step")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
