#!/usr/bin/env python3
"""Every file the build resolved for a dependency comes from a Debian package that
scripts/install-deps.sh installs (issue 54).

A fresh machine's quickstart stopped at CMake because liblammps-dev's CMake package checks for
/usr/bin/lmp, which is in Debian's `lammps`, a package that only the --tests list installed. This
reads <build>/dependency-files.tsv (written at configure by cmake/GrainbridgeDependencyFiles.cmake:
cache entries and the files the imported targets reference), names each path's package with
`dpkg -S` and requires it in the base list, or, for what only the tests resolve, in the --tests
list; a package that a listed one Depends on counts as listed (apt installs it with it). It fails
naming each file, what resolved it and its package.

Usage: dependency_packages.py <build>/dependency-files.tsv <repo>/scripts/install-deps.sh
Exit 77 (skipped) where dpkg is not there (not Debian).
"""
import os
import shutil
import subprocess
import sys


def owners_of(paths):
    """{path: the packages that own it by dpkg's database, without the :arch suffix} for every path
    dpkg knows, in one `dpkg -S` (one call per path took minutes: each reads every file list)."""
    found = {}
    if not paths:
        return found
    r = subprocess.run(["dpkg", "-S", *sorted(set(paths))], capture_output=True, text=True)
    wanted = set(paths)
    for line in r.stdout.splitlines():
        if line.startswith("diversion by"):
            continue
        packages, sep, owned = line.rpartition(": ")
        if sep and owned in wanted:
            found.setdefault(owned, set()).update(p.strip().split(":")[0] for p in packages.split(","))
    return found


def candidates(path):
    """`path`, then each hop of its symlink chain (an alternatives link such as /usr/bin/mpicc
    belongs to no package; the file it points to does), each also under the merged-/usr twin
    (/lib/x -> /usr/lib/x), since dpkg records whichever the package shipped."""
    seen = []
    p = path
    for _ in range(16):
        for q in (p, "/usr" + p if not p.startswith("/usr/") else p[len("/usr"):]):
            if q not in seen:
                seen.append(q)
        if not os.path.islink(p):
            break
        p = os.path.normpath(os.path.join(os.path.dirname(p), os.readlink(p)))
    return seen


def package_of(path, owners):
    """(the path dpkg knows, its owners) for the first hop of `path` that has an owner."""
    for q in candidates(path):
        if owners.get(q):
            return q, owners[q]
    return path, set()


def depends_of(packages):
    """{dependency: the listed package that Depends (or Pre-Depends) on it} over `packages`, every
    alternative of an `a | b` counted: apt installs these with the package, so a runtime library a
    -dev package pins (liblammps0 for liblammps-dev) needs no line of its own."""
    pulled = {}
    r = subprocess.run(["dpkg-query", "-W", "-f=${Package}\t${Pre-Depends}, ${Depends}\n", *sorted(packages)],
                       capture_output=True, text=True)
    for line in r.stdout.splitlines():
        pkg, _, depends = line.partition("\t")
        for clause in depends.split(","):
            for alternative in clause.split("|"):
                name = alternative.strip().split(" ")[0].split(":")[0]
                if name:
                    pulled.setdefault(name, pkg)
    return pulled


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    tsv, install_deps = sys.argv[1:]
    if shutil.which("dpkg") is None:
        print("no dpkg: not a Debian machine, nothing to check")
        return 77
    lists = {}
    for name in ("base", "tests"):
        out = subprocess.run([install_deps, "--list", name], capture_output=True, text=True, check=True)
        lists[name] = set(out.stdout.split())
    rows = []
    with open(tsv) as f:
        for line in f:
            if line.strip():
                rows.append(line.rstrip("\n").split("\t"))
    if not rows:
        print(f"{tsv} lists no dependency files: the configure step did not record them")
        return 1

    pulled = {name: depends_of(lists[name]) for name in lists}
    owners = owners_of([q for _, _, path in rows for q in candidates(path)])
    failures = []
    for scope, origin, path in rows:
        known, found = package_of(path, owners)
        scopes = ("base", "tests") if scope == "tests" else ("base",)
        verdict = None
        for name in scopes:
            listed = found & lists[name]
            if listed:
                shown = sorted(listed)
                names = ", ".join(shown[:3]) + (f" and {len(shown) - 3} more" if len(shown) > 3 else "")
                verdict = f"{names} [{name} list]"
                break
            via = sorted(found & pulled[name].keys())
            if via:
                verdict = f"{via[0]} [a Depends of {pulled[name][via[0]]}, {name} list]"
                break
        if verdict:
            print(f"ok    {path}  ({origin}): {verdict}")
            continue
        if not found:
            failures.append(f"{path} ({origin}) belongs to no Debian package (dpkg -S on {', '.join(candidates(path))})")
        else:
            wanted = "base" if scope == "base" else "base or --tests"
            failures.append(f"{path} ({origin}) is from Debian package {' or '.join(sorted(found))}"
                            f"{' (as ' + known + ')' if known != path else ''}, which is not in "
                            f"scripts/install-deps.sh's {wanted} list")
    print(f"{len(rows)} resolved paths checked")
    for f in failures:
        print("FAIL  " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
