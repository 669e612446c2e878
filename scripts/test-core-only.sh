#!/usr/bin/env bash
# The core component alone: configures build-core/ with the io, answers, tables, render and video
# components left out (no file code, no nlohmann-json, Cairo, FFmpeg or zlib needed), builds it and
# runs the core's tests there.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-core -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DDRAGON_WITH_IO=OFF -DDRAGON_WITH_ANSWERS=OFF -DDRAGON_WITH_TABLES=OFF -DDRAGON_WITH_RENDER=OFF -DDRAGON_WITH_VIDEO=OFF >/dev/null
cmake --build build-core -j"$(nproc)"
ctest --test-dir build-core --output-on-failure -j"$(nproc)"
