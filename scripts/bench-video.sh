#!/bin/sh
# End-to-end video speed: `dragon video` renders and encodes 300 frames at 30 fps (10 s of
# film, 1 simulated second per frame) to MP4 at 1280x720 and at 1920x1080, default options.
# Prints the frames per second dragon reports (rendering + encoding + muxing, wall clock), the
# CPU time and the file size.
#
#   scripts/bench-video.sh [path/to/dragon [output folder [more dragon video options...]]]
set -eu
dragon=${1:-build/src/dragon}
out=${2:-${TMPDIR:-/tmp}}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] && shift
for size in 1280x720 1920x1080; do
    file="$out/bench-video-$size.mp4"
    # --from 0 --to 299 --speedup 30 at 30 fps: frames at t = 0, 1, ..., 299 s.
    /usr/bin/time -f "  cpu: %U s user + %S s system, %e s wall" \
        "$dragon" video -o "$file" --size "$size" --fps 30 --from 0 --to 299 --speedup 30 "$@" 2>&1
    echo "  size: $(stat -c %s "$file") bytes"
    rm -f "$file"
done
