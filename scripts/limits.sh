#!/usr/bin/env bash
# Measures what the limits promise (issues 20 and 24), wall clock and peak resident memory of
# each run (/usr/bin/time), and prints a Markdown table:
#  - hostile input files (tests/cli/test_cli_hostile.cpp has them all): each refused at once,
#    well under a second and 100 MB;
#  - dragon sweep --workers 100000: capped, done in well under a second;
#  - each video format at its largest accepted size, 60 frames: under 2 GB resident.
#
#   scripts/limits.sh [path/to/dragon]            (the videos take about a minute on 2 cores)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dragon=$(realpath "${1:-$root/build/src/dragon}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# One row: what it is, then the command's arguments; its exit code, seconds, MB and first line
# on stderr.
row() {
  local what=$1
  shift
  local code=0
  /usr/bin/time -f "%e %M" -o time.txt timeout 60 "$dragon" "$@" >out.txt 2>err.txt </dev/null || code=$?
  read -r seconds kb < <(tail -n 1 time.txt)
  local line
  line=$(head -n 1 err.txt | cut -c1-110)
  printf '| %s | %s | %s | %.0f | %s |\n' "$what" "$code" "$seconds" "$((kb / 1024))" "${line//|/\\|}"
}
header() { printf '\n## %s\n\n| Case | Exit | Seconds | MB | First line on stderr |\n|---|---|---|---|---|\n' "$1"; }

printf 'width=0.3\n' > sc.csv
printf 'measure="max-speed"\nvary=["arc-ratio=1,2"]\n' > s2.csv
printf '[film]\nsize="320x180"\n[[shot]]\ntitle="a"\nduration=1\n' > st.png
"$dragon" sweep --vary pitch=0.5,0.6 --measure collide -q -o good.csv
(head -2 good.csv; sed -n 3p good.csv | cut -d, -f1-5) > cut.csv.partial
(head -2 good.csv; head -c 100 /dev/zero; echo) > nul.csv.partial
(head -2 good.csv; printf '0.5,'; head -c 10000000 /dev/zero | tr '\0' x; echo) > long.csv.partial
sed 's/$/\r/' good.csv > crlf.csv.partial
mkfifo fifo
python3 - <<'PY'
open('million.toml', 'w').write('[film]\nsize="320x180"\n' + '[[shot]]\ntitle="a"\nduration=1\n' * 1000000)
open('shots.toml', 'w').write('[film]\nsize="320x180"\n' + '[[shot]]\ntitle="a"\nduration=1\n' * 30000)
open('title.toml', 'w').write('[film]\nsize="320x180"\n[[shot]]\nduration=1\ntitle="' + 'x' * 900000 + '"\n')
open('key.toml', 'w').write('[dragon]\n' + 'k' * 900000 + ' = 1\n')
PY
printf '[colour]\nhead="#ff0000"\n' > typo.toml
printf 'font="No Such Font Anywhere"\n' > font.toml
sweep=(--vary pitch=0.5,0.6 --measure collide -q)

header "Hostile input files"
row "simulate over its own --scenario" simulate --to 1 --scenario sc.csv -o sc.csv
row "sweep over its own sweep file" sweep s2.csv -o s2.csv
row "film poster over its own storyboard" film st.png -o st.png --at 0.5
row "--resume, a row cut to 5 cells" sweep "${sweep[@]}" --resume -o cut.csv
row "--resume, a row of NULs" sweep "${sweep[@]}" --resume -o nul.csv
row "--resume, a 10 MB row" sweep "${sweep[@]}" --resume -o long.csv
row "--resume, CR LF lines" sweep "${sweep[@]}" --resume -o crlf.csv
row "--scenario /dev/zero" simulate --to 1 --scenario /dev/zero
row "sweep file /dev/zero" sweep /dev/zero
row "sweep merge with a part /dev/zero" sweep merge m.csv good.csv /dev/zero
row "--scenario FIFO" simulate --to 1 --scenario fifo
row "sweep file FIFO" sweep fifo
row "--scenario /proc/self/mem" simulate --to 1 --scenario /proc/self/mem
row "storyboard of 1,000,000 shots (30 MB)" film million.toml -o p.png --at 0.5
row "storyboard of 30,000 shots (1 MB)" film shots.toml -o p.png --at 0.5
row "storyboard title of 900 kB" film title.toml -o p.png --at 0.5
row "scenario key of 900 kB" simulate --to 1 --scenario key.toml
row "--theme /dev/zero" render --time 1 --theme /dev/zero -o x.png
row "theme [colour]" render --time 1 --theme typo.toml -o x.png
row "theme font not installed" render --time 1 --theme font.toml -o x.png
row "sweep --limit nan" sweep --vary arc-ratio=1,2 --measure max-speed --limit nan

header "Workers"
row "sweep of 2 scenarios, --workers 100000" sweep --vary pitch=0.5,0.6 --measure collide --workers 100000 -o w.csv

header "Videos at their largest accepted size, 60 frames"
row "mp4 8192x4352" video --size 8192x4352 --from 0 --to 6 --fps 10 -q -o big.mp4
row "mp4 8192x4352, --threads 64" video --size 8192x4352 --from 0 --to 6 --fps 10 --threads 64 -q -o big.mp4
row "mp4 3840x2160, --threads 64" video --size 3840x2160 --from 0 --to 6 --fps 10 --threads 64 -q -o big.mp4
row "webm 4096x4096" video --size 4096x4096 --from 0 --to 6 --fps 10 -q -o big.webm
row "webm 4096x4096, --threads 64" video --size 4096x4096 --from 0 --to 6 --fps 10 --threads 64 -q -o big.webm
row "gif 8192x8192" video --size 8192x8192 --from 0 --to 6 --fps 10 -q -o big.gif
row "webm 8192x8192 (refused)" video --size 8192x8192 --from 0 --to 0.1 --fps 10 -q -o big.webm
