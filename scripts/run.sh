#!/usr/bin/env bash
# The main job: install what is missing, build, answer the contest's questions into out/ and
# regenerate the figure gallery in renders/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
./build/src/dragon solve -o out
if ./build/src/dragon figures --help >/dev/null 2>&1; then
  ./build/src/dragon figures -o renders
fi
