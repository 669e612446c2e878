#!/usr/bin/env bash
# The package as another program sees it: installs build/ to a prefix, builds examples/ against
# it with the core component alone and checks with ldd that the program links no Cairo, FFmpeg or
# zlib; then builds all three examples and runs them. CI runs it after the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install build --prefix "$work/prefix" >/dev/null

cmake -S examples -B "$work/core" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" -DEXAMPLES_CORE_ONLY=ON >/dev/null
built=$(cmake --build "$work/core" 2>&1) \
  || { echo "test-consumer: the core example does not build against the installed package:" >&2; echo "$built" >&2; exit 1; }
if ldd "$work/core/frame_handles" | grep -Ei 'cairo|avcodec|avformat|avutil|swscale|libz\.'; then
  echo "test-consumer: the core example links a library of another component (above)" >&2
  exit 1
fi
"$work/core/frame_handles" | grep -q "handle 101  x  -6.237722  y   3.936008" \
  || { echo "test-consumer: frame_handles printed a wrong handle 101" >&2; exit 1; }

# A machine without FFmpeg or Cairo (pkg-config sees only toml++): the core is still
# found; the video component is not, and says why.
mkdir -p "$work/pc" "$work/probe"
cp "$(pkg-config --variable=pcfiledir tomlplusplus)/tomlplusplus.pc" "$work/pc/"
cat > "$work/probe/CMakeLists.txt" <<'PROBE'
cmake_minimum_required(VERSION 3.25)
project(probe CXX)
find_package(benchdragon REQUIRED COMPONENTS core)
find_package(benchdragon COMPONENTS video)
if(benchdragon_video_FOUND OR NOT benchdragon_video_NOT_FOUND_MESSAGE MATCHES "libav|render")
  message(FATAL_ERROR "video found, or not found without saying why: ${benchdragon_video_NOT_FOUND_MESSAGE}")
endif()
message(STATUS "probe: core found; video not found: ${benchdragon_video_NOT_FOUND_MESSAGE}")
PROBE
probe=$(PKG_CONFIG_LIBDIR="$work/pc" cmake -S "$work/probe" -B "$work/probe/build" -DCMAKE_PREFIX_PATH="$work/prefix" 2>&1) \
  && grep -q "probe: core found; video not found" <<<"$probe" \
  || { echo "test-consumer: find_package(benchdragon COMPONENTS core) failed without FFmpeg:" >&2; echo "$probe" >&2; exit 1; }

cmake -S examples -B "$work/all" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
built=$(cmake --build "$work/all" 2>&1) \
  || { echo "test-consumer: the examples do not build against the installed package:" >&2; echo "$built" >&2; exit 1; }
(cd "$work" && "$work/all/moment_png" "$work/moment.png" >/dev/null && "$work/all/ten_second_film" "$work/film.mp4" >/dev/null)
test -s "$work/moment.png" && test -s "$work/film.mp4" \
  || { echo "test-consumer: an example wrote no file" >&2; exit 1; }

# The installed tool: no path into the source tree built in, and its assets found beside it.
if strings "$work/prefix/bin/dragon" | grep -F "$root"; then
  echo "test-consumer: the installed dragon holds a path into the source tree (above)" >&2
  exit 1
fi
env -u DRAGON_ASSETS "$work/prefix/bin/dragon" render --time 10 --theme dark --size 64x64 -q -o "$work/dark.png"
test -s "$work/dark.png" || { echo "test-consumer: the installed dragon drew nothing" >&2; exit 1; }
# The installed Python package, imported from the prefix (not the build tree) with its own assets.
if [[ -d build/python/benchdragon ]]; then
  site=$(find "$work/prefix" -type d -name benchdragon -path '*-packages/*' | head -1)
  [[ -n $site ]] || { echo "test-consumer: cmake --install put no Python package in the prefix" >&2; exit 1; }
  (cd "$work" && PYTHONPATH=$(dirname "$site") /usr/bin/python3 -c '
import benchdragon as bd, sys
assert bd.__file__.startswith(sys.argv[1]), bd.__file__
assert bd.render(t=10, theme="dark", size=(64, 64)).data[:4] == b"\x89PNG"
print(f"test-consumer: the installed Python package answers Q2 at t = {bd.collide().time:.9f} s")' "$work")
fi
echo "test-consumer: the installed package builds the examples; the core one links no Cairo, FFmpeg or zlib;"
echo "test-consumer: without FFmpeg or Cairo the core component is still found;"
echo "test-consumer: the installed dragon finds its assets beside it and holds no source path"
