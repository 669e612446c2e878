#!/usr/bin/env bash
# Configures and builds into build/ (Release). Extra arguments go to cmake's configure step.
#   build.sh --tool-only   the dragon tool and the libraries it links, nothing else (scripts/run.sh)
#   build.sh               everything: the tool, the tests, the benchmarks, the Python package
# Each run says which parts it wants, so one build folder serves both in either order.
# With ccache installed (the test set of install-deps.sh), objects go through it, so that the
# component builds of scripts/test-core-only.sh reuse them instead of compiling them again.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [[ "${1:-}" == "--tool-only" ]]; then
  shift
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRAGON_BUILD_TESTS=OFF -DDRAGON_BUILD_BENCHMARKS=OFF \
    -DDRAGON_WITH_PYTHON=OFF "${launcher[@]}" "$@" >/dev/null
  cmake --build build --target dragon -j"$(nproc)"
else
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRAGON_BUILD_TESTS=ON -DDRAGON_BUILD_BENCHMARKS=ON \
    -DDRAGON_WITH_PYTHON=AUTO "${launcher[@]}" "$@" >/dev/null
  cmake --build build -j"$(nproc)"
fi
