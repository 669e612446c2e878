#!/bin/sh
# Encoding that suits the content: the README's coil-in film (`dragon video --to collision
# --speedup 20` at 30 fps, 1280x720; its frame count is printed) made with the default settings and
# with others, each measured against the same film encoded losslessly (--crf 0): file size,
# bitrate, PSNR (ffmpeg's psnr filter, its average over all frames, on the YUV planes; for the
# GIF against a lossless film of its own size) and the frames per second
# (rendering + encoding + muxing, wall clock, whole run) and the CPU time per frame. Then the
# speed at 1920x1080. Needs ffmpeg (the
# command-line tool; scripts/install-deps.sh installs it, with poppler-utils for the PDF tests).
#
#   scripts/bench-video.sh [path/to/dragon [output folder]]
set -eu
dragon=${1:-build/src/dragon}
out=${2:-${TMPDIR:-/tmp}/bench-video}
mkdir -p "$out"
film="--to collision --speedup 20 --quiet"

# One row: label, file, then the options of that setting.
row() {
    label=$1
    file=$2
    shift 2
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    /usr/bin/time -f "%U %S" -o "$out/cpu.txt" "$dragon" video -o "$out/$file" $film "$@" >/dev/null
    end=$(date +%s.%N)
    frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$out/$file")
    bytes=$(stat -c %s "$out/$file")
    ref=$out/reference.mp4
    case $file in *.gif) ref=$out/reference-small.mp4 ;; big.*) ref= ;; esac
    # Both on one clock of frame numbers (WebM keeps milliseconds, so 1/30 s steps round and
    # the filter would pair neighbouring frames), the GIF's palette pictures as YUV.
    psnr=-
    [ -n "$ref" ] && psnr=$(ffmpeg -nostdin -hide_banner -i "$out/$file" -i "$ref" -lavfi \
        "[0:v]settb=1/30,setpts=N,format=yuv420p[a];[1:v]settb=1/30,setpts=N[b];[a][b]psnr" \
        -f null - 2>&1 | sed -n 's/.*average:\([0-9.inf]*\).*/\1/p' | tail -1)
    cpu=$(awk '{ print $1 + $2 }' "$out/cpu.txt")
    # CPU time too: on a shared machine the wall clock says more about the neighbours.
    awk -v l="$label" -v b="$bytes" -v n="$frames" -v p="$psnr" -v s="$start" -v e="$end" -v c="$cpu" 'BEGIN {
        d = n / 30.0
        printf "%-46s %6.1f MB %6.2f Mbit/s %9s dB %6.1f frames/s %5.1f ms CPU/frame\n", l, b / 1e6, b * 8 / d / 1e6,
            p, n / (e - s), 1000 * c / n }'
}

"$dragon" video -o "$out/reference.mp4" $film --crf 0 --preset ultrafast --tune none >/dev/null
"$dragon" video -o "$out/reference-small.mp4" $film --size 640x360 --crf 0 --preset ultrafast --tune none >/dev/null
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$out/reference.mp4")
echo "coil-in film, 1280x720, 30 fps, $frames frames, against --crf 0:"
row "mp4 default (faster, tune animation, ref 8, subme 2, crf 23)" default.mp4
row "mp4 --preset ultrafast --tune none --crf 20" old.mp4 --preset ultrafast --tune none --crf 20
row "mp4 --preset veryfast --crf 26" veryfast26.mp4 --preset veryfast --crf 26
row "webm default (realtime, cpu-used 6, crf 35)" default.webm
row "webm --crf 32" crf32.webm --crf 32
row "gif 640x360 default (64 colours)" small.gif --size 640x360
row "gif 640x360 --colours 256" small256.gif --size 640x360 --colours 256
echo "at 1920x1080 (no reference: the speed is the point here):"
row "mp4 1920x1080 default" big.mp4 --size 1920x1080
rm -f "$out"/*.mp4 "$out"/*.webm "$out"/*.gif "$out/cpu.txt"
