#!/usr/bin/env bash
# The README's two maps: each sweep's rows (renders/*_map.csv) and its picture (renders/*_map.png),
# from the sweep files in assets/sweeps/, timed. About 40 s on 2 cores.
#
#   bash scripts/maps.sh [path/to/dragon]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dragon=$(realpath "${1:-$root/build/src/dragon}")
cd "$root"
for map in min_pitch_map max_speed_map; do
  rm -f "renders/$map.csv" "renders/$map.csv.partial"
  start=$(date +%s%N)
  "$dragon" sweep "assets/sweeps/$map.toml" -o "renders/$map.csv" --plot "renders/$map.png"
  echo "$map: $(( ($(date +%s%N) - start) / 1000000 )) ms" >&2
done
