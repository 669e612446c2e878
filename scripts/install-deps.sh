#!/usr/bin/env bash
# Installs the Debian 12 packages benchdragon needs, only those missing. Idempotent; run as root.
#   install-deps.sh run   what the tool needs to build and run (scripts/run.sh)
#   install-deps.sh       that, plus what the tests, the API reference, the Python package and the
#                         notebook need
# It says what it does in a few lines: what is missing, that it installs it, and how many packages
# that came to. apt's and dpkg's own output (a thousand lines of unpacking on a fresh machine) goes
# to a log it names, build/install-deps.log beside this checkout (/tmp if that cannot be written); on a failure the log's last lines
# are printed too.
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
  ccache                  # the component builds (scripts/test-core-only.sh) reuse the main build's objects
  # The Python package (pybind11) and its tests, sweeps on Dask, the notebook run by nbconvert,
  # and pip install . offline (setuptools and wheel from Debian).
  python3-dev pybind11-dev python3-numpy python3-pandas python3-pytest python3-hypothesis
  python3-distributed python3-tqdm python3-venv python3-pip python3-setuptools python3-wheel
  python3-xarray python3-netcdf4   # Simulation.frames(...).to_xarray() and its netCDF files
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
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

log_dir="$(cd "$(dirname "$0")/.." && pwd)/build"
mkdir -p "$log_dir" 2>/dev/null && [[ -w $log_dir ]] || log_dir=${TMPDIR:-/tmp}  # a read-only checkout
log=$log_dir/install-deps.log
: >"$log"
echo "install-deps: ${#missing[@]} of ${#packages[@]} packages missing: ${missing[*]}"
echo "install-deps: installing them with their dependencies (apt's output in $log)"
start=$SECONDS
# Runs one apt step with its output in the log; on a failure, says which and shows the log's end.
step() {
  echo "+ $*" >>"$log"
  local status=0
  "$@" >>"$log" 2>&1 </dev/null || status=$?
  if ((status != 0)); then
    echo "install-deps: $1 $2 failed (exit $status); the last lines of $log:" >&2
    tail -n 25 "$log" | sed 's/^/  | /' >&2
    exit "$status"
  fi
}
export DEBIAN_FRONTEND=noninteractive
step apt-get update
step apt-get install -y --no-install-recommends "${missing[@]}"
set_up=$(grep -c '^Setting up ' "$log" || true)
echo "install-deps: done in $((SECONDS - start)) s: ${#missing[@]} packages, $set_up set up with their dependencies"
