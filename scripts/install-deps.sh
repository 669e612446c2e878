#!/usr/bin/env bash
# Installs the Debian 12 packages benchdragon needs, only those missing. Idempotent; run as root.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libfmt-dev libtomlplusplus-dev libcli11-dev libxlsxwriter-dev nlohmann-json3-dev
  libcairo2-dev fonts-dejavu-core
  fonts-noto-cjk          # Chinese (and Japanese, Korean) glyphs: the pictures' fallback font
  doxygen                 # the API reference of include/ (scripts/api-docs.sh)
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libgtest-dev libbenchmark-dev
  python3 python3-openpyxl
  poppler-utils ffmpeg
  clang libclang-rt-14-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install-deps: all ${#packages[@]} packages present"
fi
