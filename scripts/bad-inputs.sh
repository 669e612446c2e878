#!/usr/bin/env bash
# Runs dragon on every bad input the tests try, and on the extreme but valid scenarios, and prints
# docs/bad-inputs.md: each command with its exit code and the one line it prints.
#
#   scripts/bad-inputs.sh [path/to/dragon] > docs/bad-inputs.md
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dragon=$(realpath "${1:-$root/build/src/dragon}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
printf '[dragon\nwidth = 0.3\n' > bad.toml
printf 'widht = 0.3\n' > unknown.toml
printf '[[dragon]]\nwidth = 0.3\n' > array.toml
printf 'width = nan\n' > nan.toml
printf 'pitch = 0.1\n' > narrow.toml
# Storyboards (tests/cli/test_cli_film.cpp, tests/film/test_storyboard.cpp)
small='[film]\nsize = "96x64"\nfps = 5\n'
printf "$small"'[[shot]]\nfrom = 10\nto = 12\nrate = 2\n' > story.toml
printf "$small"'[[shot]]\nname = "a"\nfrom = 1\nto = 2\nrate = 1\nspeeed = 2\n' > story-key.toml
printf "$small"'[[shot]]\nname = "late"\nfrom = 430\nto = 440\nrate = 5\n' > story-late.toml
printf "$small"'[[shot]]\nfrom = 0\nto = 2\nrate = 2\n[[shot]]\nfrom = 0\nto = 0.5\nrate = 2\ntransition = { crossfade = 0.4 }\n[[shot]]\nfrom = 0\nto = 2\nrate = 2\ntransition = { crossfade = 0.4 }\n' > story-fades.toml
printf "$small"'[[shot]]\nfrom = "collision * 2"\nto = 10\nrate = 5\n' > story-moment.toml
printf "$small"'[[shot]]\nrate = 5\nslow = { at = 1, within = 1, rate = 1 }\nsplit = [{}, {}]\n' > story-split.toml
printf "$small"'[[shot]]\nfrom = 0\nto = 10\nrate = 5\npitch = 0.2\n' > story-pitch.toml

# One table row: the command, its exit code, and the first line of stderr (or, for a run that
# works, the first line of stdout; with row_last, its last line). Pipes are escaped for the table.
pick=head
row_last() { pick=tail; row "$@"; pick=head; }
row() {
  local code=0
  "$dragon" "$@" >"${stdout_to:-out.txt}" 2>err.txt </dev/null || code=$?
  local line
  if [ "$code" -eq 0 ]; then line="(works) $($pick -n 1 out.txt)"; else line=$(head -n 1 err.txt); fi
  [ "$code" -eq 0 ] && [ ! -s out.txt ] && line="(works) $(head -n 1 err.txt)"
  [ "$code" -ne 0 ] && [ "$(wc -l <err.txt)" -ne 1 ] && line="$line (+$(($(wc -l <err.txt) - 1)) more lines)"
  local shown="" a quotes="''"
  for a in "$@"; do shown+="${shown:+ }${a:-$quotes}"; done  # an empty argument shows as ''
  shown=${shown//$'\n'/\\n}  # a line break in an argument, escaped as the program shows it
  [ -n "${shown_as:-}" ] && shown=$shown_as
  printf '| `dragon %s` | %s | %s |\n' "$shown" "$code" "${line//|/\\|}"
  rm -rf out.* a.* film* x.* *.png *.mp4 *.gif *.webm out
}
header() { printf '\n## %s\n\n| Input | Exit | Message |\n|---|---|---|\n' "$1"; }

cat <<'TEXT'
# Bad inputs and extreme scenarios

What `dragon` says to each bad input the tests try, and to extreme but valid scenarios. Bad input
gets one line on stderr and exit code 2, and leaves no output file (nor a temporary one); a run
that fails for any other reason exits 1. Regenerate with `scripts/bad-inputs.sh > docs/bad-inputs.md`.
TEXT

header "Scenario values and files (tests/cli/test_cli_core.cpp)"
row simulate --pitch 0 -o out.csv
row simulate --pitch -0.5 -o out.csv
row simulate --pitch nan -o out.csv
row simulate --speed 0 -o out.csv
row simulate --speed inf -o out.csv
row simulate --head-length -1 -o out.csv
row simulate --body-length 0 -o out.csv
row simulate --width nan -o out.csv
row simulate --hole-offset 1.1 -o out.csv
row simulate --bench-count 0 -o out.csv
row simulate --pitch 0.25 -o out.csv
row simulate --start-turn 0 -o out.csv
row simulate --start-turn -3 -o out.csv
row simulate --to 5000 -o out.csv
row simulate --from 5 --to 1 -o out.csv
row simulate --step 0 -o out.csv
row simulate --bogus 1 -o out.csv
row simulate --pitch abc -o out.csv
row simulate --path circle -o out.csv
row simulate --scenario /nonexistent.toml -o out.csv
row simulate -o /nonexistent-dir/out.csv
row simulate -o out.csv.txt
row collide --pitch 0
row min-pitch --lo 0.6 --hi 0.5
row min-pitch --grid 0
row min-pitch --grid 1e-9
row solve -o /proc/forbidden
row simulate --to 1 --scenario bad.toml
row simulate --to 1 --scenario unknown.toml
row simulate --to 1 --scenario array.toml
row simulate --to 1 --scenario nan.toml
row simulate --to 1 --scenario /tmp
row simulate --hole-offset nan -o out.csv
row min-pitch --hi 1e308
row min-pitch --grid 1e-300
row simulate --step 1e-300 -o out.csv
row simulate --digits 18 -o out.csv
row simulate --digits 3 -o out.xlsx
row collide --digits 3
row simulate --to 1 -o /proc/x.csv

# The same under a file size limit of 8 KiB: every write past it fails as on a full disk.
row_full() { (trap '' XFSZ; ulimit -f 8; row "$@"); }

header "A full disk: the file size limited to 8 KiB (tests/cli/test_cli_outputs.cpp)"
row_full render --time 1 -o x.png
row_full simulate --to 100 -o x.xlsx
row_full solve --only q1 -o out

header "Command line and flags (tests/cli/test_cli_core.cpp, tests/cli/test_cli_flags.cpp)"
row
row simulat --to 1
row foo
row simulate --pich 0.6
row simulate --body-count 3
row simulate 5
row simulate --pitch '' -o out.csv
row simulate --pitch= -o out.csv
row simulate -o ''
row solve -o ''
row collide --to ''
row simulate --scenario ''
row turnaround --pitch 5
row max-speed --start-turn 3
row min-pitch --pitch 0.1
row min-pitch --path turnaround
row solve --path turnaround
row figures --path turnaround
row simulate --turn-pitch 2 -o out.csv
row simulate --path turnaround --pitch 0.6 -o out.csv
row solve --only q4 --pitch 0.5
row turnaround --no-clearance --to 5
row figures --list --scale 2
row max-speed --digits 3

header "dragon sweep (tests/cli/test_cli_sweep.cpp, tests/cli/test_cli_sweep_resume.cpp)"
row sweep --vary width=0.2:0.4 --measure collide -o out.csv
row sweep --vary width=0.2:0.4:two --measure collide -o out.csv
row sweep --vary colour=1,2 --measure collide -o out.csv
row sweep --vary width=0.3,0.3 --measure collide -o out.csv
row sweep --vary bench-count=10:11:3 --measure collide -o out.csv
row sweep --vary pitch=0.5,0.6 --measure min-pitch -o out.csv
row sweep --vary width=0.3,0.4 --measure bogus -o out.csv
row sweep --vary width=0.3,0.4 -o out.csv
row sweep --measure collide -o out.csv
row sweep --vary width=0.3,0.4 --measure collide --width 0.3 -o out.csv
row sweep --vary width=0.3,0.4 --measure max-speed --pitch 0.6 -o out.csv
row sweep --vary width=0.3,0.4 --measure collide --limit 3 -o out.csv
row sweep --vary width=0.3,0.4 --measure min-pitch --lo width-0.1 -o out.csv
row sweep --vary width=0.3,0.4 --measure collide --shard 0/2 -o out.csv
row sweep --vary width=0.3,0.4 --measure collide -o out.txt
row sweep --vary width=0.3,0.4 --measure collide --resume
row sweep --vary width=0.3 --measure collide --plot x.png
row sweep --vary width=0.3,0.4 --measure collide --plot x.jpg
row sweep merge out.csv
row sweep merge out.csv --bogus
row_last sweep --vary width=0.3,0.6 --bench-count 20 --measure collide --workers 1

header "dragon video (tests/cli/test_cli_video.cpp)"
row video -o a.mp4 --size 65x48 --to 1
row video -o a.webm --size 64x47 --to 1
row video -o a.avi --size 64x48 --fps 5 --from 0 --to 1
row video -o film --size 64x48 --fps 5 --from 0 --to 1
row video -o /nonexistent-dragon-dir/a.mp4 --size 64x48 --fps 5 --from 0 --to 1
row video -o a.mp4 --fps 0 --to 1
row video -o a.mp4 --size 64x48 --from 5 --to 5
row video -o a.gif --size 64x48 --from 5 --to 2
row video -o a.mp4 --size 64x48 --to 100000
row video -o a.mp4 --size 64x48 --to soon
row video -o a.mp4 --size big --to 1
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --preset glacial
row video -o a.gif --size 64x48 --fps 5 --from 0 --to 1 --colours 1
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --speedup -1
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --crf -1
row video -o a.gif --size 64x48 --fps 5 --from 0 --to 1 --crf 20
row video -o a.webm --size 64x48 --fps 5 --from 0 --to 1 --preset fast
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --colours 64
row video -o a.mp4 --size 64x48 --fps 1e-9 --to 1
row video -o a.mp4 --size 64x48 --speedup 1e-300 --to 1
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --hold 3601
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --zoom nan
row video -o a.mp4 --size 1280x720 --fps 5 --to 1 --follow-head --zoom 1e-9
row video -o a.mp4 --size 64x48 --fps 5 --from 0 --to 1 --tune cartoon
row video -o a.gif --size 64x48 --fps 5 --from 0 --to 1 --tune film
row video -o a.mp4 --size 8192x8192 --fps 5 --to 1
row video -o a.webm --size 8192x8192 --fps 5 --to 1

header "dragon film (tests/cli/test_cli_film.cpp, tests/film/)"
row film story-key.toml -o a.mp4
row film story-late.toml -o a.mp4
row film story-fades.toml -o a.mp4
row film story-moment.toml -o a.mp4
row film story-split.toml -o a.mp4
row film story-pitch.toml -o a.mp4
row film story.toml -o a.png
row film story.toml -o a.png --at 99
row film story.toml -o a.mp4 --at 1
row film story.toml -o a.webm --tune film
row film nowhere.toml -o a.mp4

header "dragon render and figures (tests/render/test_cli_render.cpp)"
row render --time 100 -o bad.bmp
row render -o x.png
row render --time 100 --size 10x10 -o x.png
row render --time 100 --theme sepia -o x.png
row render --time 1e6 -o x.png
row render --time 100 -o /no/such/dir/x.png
row render --time 0 --zoom nan -o x.png
row render --time 0 --zoom 1e-300 -o x.png
row render --time 0 --zoom 1e300 -o x.png
row render --time 0 --centre nan 0 --zoom 1 -o x.png
row render --time 0 --centre 1e300 0 --zoom 1 -o x.png
row render --time 0 --zoom 1e-9 -o x.png
row render --collision --zoom 1e-9 -o x.png
row figures --only no_such_figure -o figs
row render --time 1 --theme /tmp -o x.png

header "Hostile and corrupt input files (tests/cli/test_cli_hostile.cpp; times and memory: scripts/limits.sh)"
# Each made just before its row (row removes *.png and the like after each).
printf 'width=0.3\n' > sc.csv; row simulate --to 1 --scenario sc.csv -o sc.csv
ln -sf sc.csv link.csv; row simulate --to 1 --scenario sc.csv -o link.csv
printf 'measure="max-speed"\nvary=["arc_ratio=1,2"]\n' > s2.csv; row sweep s2.csv -o s2.csv
printf 'scenario="sc.csv"\nmeasure="max-speed"\nvary=["arc_ratio=1,2"]\n' > s3.toml; row sweep s3.toml -o sc.csv
printf '[film]\nsize="320x180"\n[[shot]]\ntitle="a"\nduration=1\n' > st.png; row film st.png -o st.png --at 0.5
printf '[colours]\nhead="#ff0000"\n' > t.png; row render --time 1 --theme ./t.png -o t.png
"$dragon" sweep --vary pitch=0.5,0.6 --measure collide -q -o good.csv
row sweep merge good.csv good.csv
(head -2 good.csv; sed -n 3p good.csv | cut -d, -f1-5) > cut.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o cut.csv
(head -2 good.csv; sed -n 3p good.csv | sed 's/$/,more/') > more.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o more.csv
(head -2 good.csv; head -c 100 /dev/zero; echo) > nul.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o nul.csv
(head -2 good.csv; printf '0.5,'; head -c 10000000 /dev/zero | tr '\0' x; echo) > long.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o long.csv
sed 's/$/\r/' good.csv > crlf.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o crlf.csv
sed 's/"0.6"/"0.7"/' good.csv > other.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o other.csv
ln -sf good.csv linked.csv.partial
row sweep --vary pitch=0.5,0.6 --measure collide --resume -o linked.csv
(head -3 good.csv; sed -n 4p good.csv | cut -d, -f1-2) > part.csv
row sweep merge m.csv part.csv
row simulate --to 1 --scenario /dev/zero
row sweep /dev/zero
printf 'scenario="/dev/zero"\nmeasure="max-speed"\nvary=["arc_ratio=1,2"]\n' > s4.toml; row sweep s4.toml
row sweep merge m.csv good.csv /dev/zero
mkfifo fifo
row simulate --to 1 --scenario fifo
row sweep fifo
row sweep merge m.csv good.csv fifo
row simulate --to 1 --scenario /proc/self/mem
row sweep /proc/self/mem
python3 - <<'PY'
open('million.toml', 'w').write('[film]\nsize="320x180"\n' + '[[shot]]\ntitle="a"\nduration=1\n' * 1000000)
open('shots.toml', 'w').write('[film]\nsize="320x180"\n' + '[[shot]]\ntitle="a"\nduration=1\n' * 30000)
open('title.toml', 'w').write('[film]\nsize="320x180"\n[[shot]]\nduration=1\ntitle="' + 'x' * 900000 + '"\n')
open('captions.toml', 'w').write('[film]\nsize="320x180"\n[[shot]]\nfrom=0\nto=1\nrate=1\ncaptions=[' + '{text="a"},' * 21 + ']\n')
open('key.toml', 'w').write('[dragon]\n' + 'k' * 900000 + ' = 1\n')
PY
row film million.toml -o poster.png --at 0.5
row film shots.toml -o poster.png --at 0.5
row film title.toml -o poster.png --at 0.5
row film captions.toml -o poster.png --at 0.5
row sweep --vary arc-ratio=1,2 --measure max-speed --limit nan
printf 'measure="max-speed"\nvary=["arc_ratio=1,2"]\n[max-speed]\nlimit="1e999"\n' > s5.toml; row sweep s5.toml
row sweep --vary width=0.3,0.31 --measure min-pitch --grid 0
row sweep --vary width=0.3,0.31 --measure min-pitch --lo 0.5 --hi 0.4
printf 'bogus=1\n' > th1.toml; row render --time 1 --theme th1.toml -o x.png
printf '[colour]\nhead="#ff0000"\n' > th2.toml; row render --time 1 --theme th2.toml -o x.png
cp story.toml th3.toml; row render --time 1 --theme th3.toml -o x.png
python3 -c "print('[' + '.'.join(['a'] * 10000) + ']')" > th4.toml; row render --time 1 --theme th4.toml -o x.png
printf 'font="No Such Font Anywhere"\n' > th5.toml; row render --time 1 --theme th5.toml -o x.png
row render --time 1 --theme /dev/zero -o x.png
row render --time 1 --theme fifo -o x.png
row render --time 1 --theme ./fifo -o x.png
printf 'width = 9223372036854775807\n' > wide.toml; row simulate --to 1 --scenario wide.toml
ln -sf /dev/zero zero.toml
printf '[film]\nsize="320x180"\nscenario="zero.toml"\n[[shot]]\nto=3\nrate=1\n' > story-zero.toml; row film story-zero.toml -o x.mp4
printf '[film]\nsize="320x180"\n[[shot]]\nfrom=[1]\nto=3\nrate=1\n' > story-list.toml; row film story-list.toml -o x.mp4
printf '[fixed]\n"wid\\u0000th" = 1\n' > s6.toml; row sweep s6.toml --vary arc-ratio=1 --measure max-speed
row simulate --to 1 --scenario key.toml
shown_as="sweep --measure max-speed --vary arc-ratio=1,1,...,1 (50,000 values)" \
  row sweep --measure max-speed --vary "arc-ratio=$(python3 -c "print(','.join(['1'] * 50000))")"
row simulate --to 1 -o $'a\nb.csv'
rm -f $'a\nb.csv'

header "Files keep their protections (tests/cli/test_cli_protections.cpp)"
"$dragon" render --time 1 --size 64x64 -q -o prot.png; chmod 444 prot.png
row render --time 2 --size 64x64 -o prot.png
rm -f prot.png
ln -sf nowhere.csv dangling.csv; row simulate --to 1 -o dangling.csv
ln -sf /dev/null null.csv; row simulate --to 1 -o null.csv
shown_as="video --to collision --size 64x48 --fps 1 --speedup 100 -o x.gif > /dev/full (then: ls x.gif finds nothing)" \
  stdout_to=/dev/full row video --to collision --size 64x48 --fps 1 --speedup 100 -o x.gif
row_workers() { local out; out=$("$dragon" "$@" 2>&1 >/dev/null | head -n 1); printf '| `dragon %s` | 0 | %s |\n' "$*" "$out"; }
row_workers sweep --vary pitch=0.5,0.6 --measure collide --workers 100000

header "Out of range (tests/cli/test_cli_extremes.cpp)"
row simulate --start-turn 1e5 --to 1
row simulate --pitch 2000 --to 1
row simulate --speed 1e10 --to 0
row simulate --hole-offset 1.0999 --body-length 2.2 --to 0
row simulate --path turnaround --from 1e7 --to 1e7
row simulate --bench-count 1000000 --body-length 20 --to 0

header "The end of the valid motion: refused past it, reported where it cuts a search short (tests/cli/test_cli_valid_motion.cpp)"
row simulate --from 432.9 --to 432.93 --step 0.01
row simulate --path turnaround --arc-ratio 3 --from 15.1477 --to 15.1478 --step 0.00001
row render --time 433 -o x.png
row video --from 430 --to 433 --size 64x48 -o x.mp4
row_last collide --path turnaround --arc-ratio 3 --from -100 --to 100
row_last collide --pitch 0.7
row collide --from 100 --to 50
row collide --to inf
row_last max-speed --arc-ratio 3
row max-speed --head-length 6 --arc-ratio 1
row_last turnaround --arc-ratio 3
row min-pitch --lo 0.46 --hi 0.5
row min-pitch --lo 0.36 --hi 0.4

header "Extreme but valid scenarios (tests/cli/test_cli_extremes.cpp)"
row_last simulate --bench-count 1 --to 3
row collide --bench-count 1
row render --bench-count 1 --collision -o x.png
row video --bench-count 1 --size 64x48 -o x.mp4
row_last simulate --bench-count 10000 --to 0
row render --bench-count 10000 --time 10 --size 64x64 -o x.png
row_last simulate --pitch 0.3000001 --to 1
row collide --pitch 0.3000001
row render --pitch 0.3000001 --collision -o x.png
row_last simulate --speed 1e-6 --to 300 --step 100
row_last max-speed --speed 1e-6
row_last turnaround --speed 1e-6
row collide --speed 1e-6
row collide --speed 100
row simulate --speed 100 --to 5
row_last turnaround --speed 100 --from -1 --to 1
row max-speed --speed 1e4
row collide --from 420
row video --from 420 --size 64x48 -o x.mp4
row_last simulate --from 442.5902564 --to 442.5902564
row simulate --to 443
row collide --from 500
row video --turn-radius 20 --to boundary --size 64x48 -o x.mp4
row min-pitch --turn-radius 20 --lo 0.4 --hi 0.45
row min-pitch --turn-radius 20 --lo 1.3 --hi 1.4
row turnaround --turn-radius 20 --no-clearance
row_last turnaround --turn-radius 20
row_last max-speed --turn-radius 20
row min-pitch --scenario narrow.toml --lo 0.44 --hi 0.46 --grid 0.01
row_last max-speed --scenario narrow.toml
row turnaround --speed 1000

# The slow ones, run and timed: the wall time this run took, and the line the program printed
# (its first line, or with timed_last its last: the answer), so no number here is typed by hand.
timed_last() { pick=tail; timed "$@"; pick=head; }
timed() {
  local code=0 start end
  start=$(date +%s%N)
  "$dragon" "$@" >out.txt 2>err.txt </dev/null || code=$?
  end=$(date +%s%N)
  local line
  if [ "$code" -eq 0 ]; then line="(works) $($pick -n 1 out.txt)"; else line=$(head -n 1 err.txt); fi
  printf '| `dragon %s` | %s | %s s | %s |\n' "$*" "$code" "$(awk -v ns=$((end - start)) 'BEGIN { t = ns / 1e9; if (t >= 10) printf "%.0f", t; else printf "%.2g", t }')" \
    "${line//|/\\|}"
  rm -rf out.* a.* x.*
}

build_type=$(grep -m1 CMAKE_BUILD_TYPE: "$(dirname "$dragon")/../CMakeCache.txt" 2>/dev/null | cut -d= -f2 || true)
printf '\n## Slow inputs, timed\n\nWall time of each run when this file was made, by the %s build on %s cores (load average\n' \
  "${build_type:-unknown}" "$(nproc)"
printf '%s as they started: other work on the machine slows them), and the answer line it printed.\n' \
  "$(cut -d' ' -f1 /proc/loadavg)"
printf '\n| Input | Exit | Time | Answer |\n|---|---|---|---|\n'
timed_last turnaround --speed 100
timed_last turnaround --bench-count 10000
timed max-speed --bench-count 10000
timed collide --bench-count 10000
