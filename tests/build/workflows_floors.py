#!/usr/bin/env python3
"""workflows/ is built as floors (workflows/CMakeLists.txt): each target links only the targets
below it. A file that includes a header of a folder above its own would point back up, and the
floors would hold only until the next link error. This checks every #include "workflows/<folder>/"
of every file under workflows/ against the folders its own folder's target may use, and names each
file and line that points up.

Usage: workflows_floors.py <project source dir>
"""
import pathlib
import re
import sys

# The target of each folder and the targets each target links (as workflows/CMakeLists.txt).
TARGET = {
    "params": "params", "contract": "contract", "driver": "driver", "report": "report",
    "closures": "closures", "stages": "stages", "config": "plan", "plan": "plan",
    "exec": "exec", "status": "exec", "commands": "commands",
}
LINKS = {
    "params": [], "contract": [], "driver": ["contract"], "report": ["contract"], "closures": ["params"],
    "stages": ["params", "contract", "driver", "report", "closures"], "plan": ["stages", "params"],
    "exec": ["plan", "stages"], "commands": ["exec", "plan", "report", "closures", "stages"],
}


def reachable(target):
    seen, todo = {target}, [target]
    while todo:
        for below in LINKS[todo.pop()]:
            if below not in seen:
                seen.add(below)
                todo.append(below)
    return seen


def main():
    root = pathlib.Path(sys.argv[1]) / "workflows"
    include = re.compile(r'^\s*#include "workflows/([a-z_]+)/')
    problems = []
    folders = sorted(p.name for p in root.iterdir() if p.is_dir())
    for folder in folders:
        if folder not in TARGET:
            problems.append(f"workflows/{folder}/: a folder no floor names; add it to workflows/CMakeLists.txt and here")
            continue
        allowed = reachable(TARGET[folder])
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".hpp", ".cpp"):
                continue
            for number, line in enumerate(path.read_text().splitlines(), 1):
                m = include.match(line)
                if not m:
                    continue
                used = m.group(1)
                if used not in TARGET:
                    problems.append(f"{path.relative_to(root.parent)}:{number}: includes unknown folder workflows/{used}/")
                elif TARGET[used] not in allowed:
                    problems.append(f"{path.relative_to(root.parent)}:{number}: workflows_{TARGET[folder]} includes "
                                    f"workflows/{used}/ (workflows_{TARGET[used]}), which is not below it")
    for p in problems:
        print(p)
    print(f"{len(folders)} folders checked, {len(problems)} include(s) pointing up or unknown")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
