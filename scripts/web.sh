#!/usr/bin/env bash
# Builds docs/explorer.html, the page: the library's core and answers compiled to WebAssembly by
# emscripten (web/CMakeLists.txt adds the same CMake build of the core), web/bindings.cpp, and
# the page's scripts, type-checked and assembled into one self-contained file. Installs what it
# needs first (Debian's emscripten and chromium-headless-shell, Node.js, and the page's npm
# packages from web/package-lock.json). Run as root from anywhere.
#   web.sh              install, build, assemble docs/explorer.html
#   web.sh --test-deps  only install what the page's tests need (the browser, Node.js, npm packages)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(chromium-headless-shell)
[[ "${1:-}" == "--test-deps" ]] || packages+=(emscripten cmake ninja-build)
command -v node >/dev/null && command -v npm >/dev/null || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "web: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# Debian's emscripten finds its acorn in Debian's node folder; another Node.js build (NodeSource's)
# does not look there by itself.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# The page's npm packages (the type checker, the browser driver of tests/web), as the lock file pins them.
if ! cmp -s web/package-lock.json web/node_modules/.installed-lock.json 2>/dev/null; then
  (cd web && npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.installed-lock.json)
fi
[[ "${1:-}" == "--test-deps" ]] && exit 0

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
emcmake cmake -S web -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build build-web --target dragon_engine -j"$(( $(nproc) < 2 ? $(nproc) : 2 ))"
(cd web && node node_modules/typescript/bin/tsc -p tsconfig.json)
node web/assemble.mjs build-web/dragon_engine.js docs/explorer.html
