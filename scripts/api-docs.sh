#!/usr/bin/env bash
# The API reference of include/dragon/ by Doxygen, into build/api/html (open index.html). The
# headers' plain // comments reach Doxygen through scripts/doxygen-filter.py. Warnings are
# errors (docs/api/Doxyfile): an undocumented public symbol fails this script, and CI with it.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v doxygen > /dev/null; then
    echo "api-docs: doxygen is not installed (scripts/install-deps.sh installs it)" >&2
    exit 1
fi
mkdir -p build/api
if ! doxygen docs/api/Doxyfile 2> build/api/warnings.txt; then
    n=$(grep -c "not documented" build/api/warnings.txt || true)
    echo "api-docs: doxygen failed ($n undocumented symbols); the first warnings:" >&2
    head -20 build/api/warnings.txt >&2
    exit 1
fi
echo "api-docs: build/api/html/index.html"
