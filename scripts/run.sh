#!/usr/bin/env bash
# The main job: install what is missing, build, answer the contest's questions into out/ and
# regenerate the figure gallery in renders/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh run
bash scripts/build.sh --tool-only
mkdir -p out
./build/src/dragon solve -o out
./build/src/dragon figures -o renders --scale 0.8   # about 800 px each, 640 KB in all
./build/src/dragon video -o renders/coil.gif --size 400x300 --colours 48 --fps 8 --speedup 40 --to collision --no-legend
# Poster frames of the contest's storyboard film: its first contact, two pitches side by side, the turnaround
for at in 27 45 63; do
    ./build/src/dragon film assets/films/contest.toml -o "renders/film_${at}s.png" --at "$at" --size 640x360
done
