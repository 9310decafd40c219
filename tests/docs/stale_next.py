#!/usr/bin/env python3
"""No page of the user's documentation calls a shipped thing "next" (issue 54).

The README's status once said "Next: several solids phases (the binary Goldschmidt bed), then
TF-DEM" long after both had shipped, and docs/tfdem.md called the tfdem stage "issue 27's next
part". A sentence of README.md or docs/*.md that announces something as to come (Next:, next
part, "X next", will be, not yet) and names a shipped stage type (the headings of docs/stages.md,
which a test keeps equal to `grainbridge stages`), a shipped config (configs/*.json) or what the
prose calls them (PROSE_NAMES) fails, with its file and line.

Usage: stale_next.py <repo>
"""
import glob
import os
import re
import sys

# Words that put the thing a sentence names in the future.
FUTURE = re.compile(r"\bNext\s*:|\bnext part\b|\b[\w`-]+\s+next\b\s*[);.,]|\bwill (?:be|come|run|add)\b|\bnot yet (?:built|shipped|there)\b|"
                    r"\bcomes? next\b|\bis next\b", re.IGNORECASE)


# What the prose calls shipped things, beside their stage type or config names.
PROSE_NAMES = {"TF-DEM", "multi-fluid", "several solids phases", "mixtures", "binary Goldschmidt bed",
               "engine lammps", "combine", "closure loop"}


def shipped_names(repo):
    names = set(PROSE_NAMES)
    with open(os.path.join(repo, "docs/stages.md")) as f:
        for line in f:
            m = re.match(r"^## `([a-z_]+)`", line)
            if m:
                names.add(m.group(1))
    names.update(os.path.basename(p)[: -len(".json")] for p in glob.glob(os.path.join(repo, "configs/*.json")))
    return names


def sentences(text):
    """(line number, sentence) over a Markdown page, code blocks left out."""
    in_code = False
    buf, start = [], 0
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith("```"):
            in_code = not in_code
            continue
        if in_code:
            continue
        if not line.strip():
            if buf:
                yield start, " ".join(buf)
            buf = []
            continue
        if not buf:
            start = number
        buf.append(line.strip().lstrip("> ").strip())
    if buf:
        yield start, " ".join(buf)


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    repo = sys.argv[1]
    names = shipped_names(repo)
    if not names:
        print("no stage types found in docs/stages.md")
        return 1
    name_re = re.compile(r"(?<![\w/.-])`?(" + "|".join(sorted(map(re.escape, names), key=len, reverse=True)) +
                         r")(?:\.json)?`?(?![\w-])", re.IGNORECASE)
    pages = [os.path.join(repo, "README.md")] + sorted(glob.glob(os.path.join(repo, "docs/*.md")))
    stale = []
    for page in pages:
        with open(page) as f:
            text = f.read()
        for number, paragraph in sentences(text):
            for sentence in re.split(r"(?<=[.!?])\s+(?=[A-Z`(])", paragraph):
                future = FUTURE.search(sentence)
                named = name_re.search(sentence)
                if future and named:
                    stale.append(f"{os.path.relpath(page, repo)}:{number}: \"{future.group(0).strip()}\" beside shipped "
                                 f"\"{named.group(1)}\": {sentence[:200]}")
    for s in stale:
        print("STALE " + s)
    print(f"{len(pages)} pages read, {len(stale)} sentences call a shipped stage type or config next")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
