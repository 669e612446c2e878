#!/usr/bin/env bash
# The main job: install what is missing, build, answer the contest's questions into out/ and
# regenerate the figure gallery in renders/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh run
bash scripts/build.sh --tool-only
mkdir -p out
./build/src/dragon solve -o out
./build/src/dragon figures -o renders --scale 0.8 --data   # about 800 px each, 640 KB in all; each figure's numbers as CSV
# Two figures in Chinese and two at a column's width (3.5 in, text 8 pt, at 200 dpi), as the README shows them
./build/src/dragon figures -o renders/zh --lang zh --scale 0.8 --only fig4_first_contact,plot_s_curve
./build/src/dragon figures -o renders/column --print column --dpi 200 --only plot_speeds,fig1_link_geometry
./build/src/dragon video -o renders/coil.gif --size 400x300 --colours 48 --fps 8 --speedup 40 --to collision --no-legend
# Poster frames of the contest's storyboard film: its first contact, two pitches side by side, the turnaround
for at in 27 45 63; do
    ./build/src/dragon film assets/films/contest.toml -o "renders/film_${at}s.png" --at "$at" --size 640x360
done
