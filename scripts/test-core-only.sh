#!/usr/bin/env bash
# Each component alone, with the ones above it switched off: the core by itself (build-core/: no
# file code (io), nlohmann-json, Cairo, FFmpeg or zlib needed), then every component but video (build-novideo/:
# core, answers, tables and render without FFmpeg, and so without the tool). Each builds and runs
# its own tests there: no component's tests need a layer above it or the tool.
# With ccache (scripts/build.sh uses it too) most objects are the main build's, not compiled again.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
configure() {  # folder, then the components' switches
  local dir=$1
  shift
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRAGON_BUILD_BENCHMARKS=OFF "${launcher[@]}" "$@" >/dev/null
  cmake --build "$dir" -j"$(nproc)"
  ctest --test-dir "$dir" --output-on-failure -j"$(nproc)"
}
configure build-core -DDRAGON_WITH_IO=OFF -DDRAGON_WITH_ANSWERS=OFF -DDRAGON_WITH_TABLES=OFF -DDRAGON_WITH_RENDER=OFF -DDRAGON_WITH_VIDEO=OFF
configure build-novideo -DDRAGON_WITH_VIDEO=OFF
