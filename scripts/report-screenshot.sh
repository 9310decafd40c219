#!/usr/bin/env bash
# Regenerates docs/img/quickstart-report.png, the README's picture of the quickstart report:
# runs configs/quickstart.json into the repository's results/ (cached runs are fast), writes its
# report, then has tests/integration/report_browser.py check it in headless Chromium and save the
# first screen (1280x800). The screenshot is saved even when checks fail; the exit status says
# whether they passed. Uses $GRAINBRIDGE, else build-release/bin/grainbridge, else build/bin/grainbridge.
# Needs chromium, chromium-driver and python3-selenium (scripts/install-deps.sh --tests).
set -euo pipefail
cd "$(dirname "$0")/.."

grainbridge=${GRAINBRIDGE:-}
if [[ -z "$grainbridge" ]]; then
  if [[ -x build-release/bin/grainbridge ]]; then
    grainbridge=build-release/bin/grainbridge
  else
    grainbridge=build/bin/grainbridge
  fi
fi
if [[ ! -x "$grainbridge" ]]; then
  echo "no grainbridge at $grainbridge: build first (cmake --preset release && cmake --build build-release)" >&2
  exit 1
fi

"$grainbridge" run configs/quickstart.json
# Its first line ending in .html is the report's path (a text summary may follow).
out=$("$grainbridge" report configs/quickstart.json)
report=$(grep -m1 '\.html$' <<<"$out")
python3 tests/integration/report_browser.py --report "$report" --screenshot docs/img/quickstart-report.png
