#!/usr/bin/env bash
# Installs the Debian 12 packages benchdragon needs, only those missing. Idempotent; run as root.
#   install-deps.sh run   what the tool needs to build and run (scripts/run.sh)
#   install-deps.sh       that, plus what the tests, the API reference, the Python package and the
#                         notebook need
set -euo pipefail
run_packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libfmt-dev libtomlplusplus-dev libcli11-dev zlib1g-dev nlohmann-json3-dev
  libcairo2-dev fonts-dejavu-core
  fonts-noto-cjk          # Chinese (and Japanese, Korean) glyphs: the pictures' fallback font
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
)
test_packages=(
  libgtest-dev libbenchmark-dev
  python3 python3-openpyxl
  poppler-utils ffmpeg
  clang libclang-rt-14-dev
  doxygen                 # the API reference of include/, built in CI (scripts/api-docs.sh)
  # The Python package (pybind11) and its tests, sweeps on Dask, the notebook run by nbconvert,
  # and pip install . offline (setuptools and wheel from Debian).
  python3-dev pybind11-dev python3-numpy python3-pandas python3-pytest python3-hypothesis
  python3-distributed python3-tqdm python3-venv python3-pip python3-setuptools python3-wheel
  jupyter-nbconvert python3-nbformat python3-ipykernel python3-ipywidgets
)
case "${1:-all}" in
  run) packages=("${run_packages[@]}") ;;
  all) packages=("${run_packages[@]}" "${test_packages[@]}") ;;
  *) echo "install-deps: '$1' is not a set of packages: give run, or nothing for all" >&2; exit 2 ;;
esac
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
