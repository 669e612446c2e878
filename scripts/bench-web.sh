#!/usr/bin/env bash
# The page's speed in Debian's headless Chromium: ready time, frame time while playing, Q2 and
# all answers after a change (tests/web/bench.mjs). Prints a Markdown table for docs/performance.md.
# Installs the browser and the npm packages if missing (scripts/web.sh --test-deps). Run on an idle machine.
#   RUNS=5 bash scripts/bench-web.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/web.sh --test-deps >&2
node tests/web/bench.mjs
