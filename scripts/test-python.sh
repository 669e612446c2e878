#!/usr/bin/env bash
# The Python package's tests, on the build that scripts/build.sh made: pytest (every call against
# the tool, arrays against its CSV, errors, sweeps on threads, processes and Dask, Ctrl-C,
# properties with hypothesis, the example notebook run by nbconvert as a user runs it); and
# `pip install .` offline into a fresh venv from that build, imported from outside the source tree.
# Skips, saying why, when the build has no Python package.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
py=/usr/bin/python3
[[ -x $py ]] || py=$(command -v python3)
if [[ ! -f build/python/benchdragon/__init__.py ]]; then
  echo "test-python: skipped: build/ has no Python package (pybind11-dev and python3-dev not found at configure)"
  exit 0
fi
export PYTHONPATH=$root/build/python DRAGON_BIN=$root/build/src/dragon
"$py" -m pytest tests/python -q -p no:cacheprovider

# pip install . as a user would (no index, Debian's setuptools), reusing the tested build.
venv=$root/build/venv
rm -rf "$venv"
"$py" -m venv --system-site-packages "$venv"
DRAGON_PYTHON_BUILD_DIR=$root/build "$venv/bin/pip" install . --no-index --no-build-isolation -q
(cd /tmp && env -u PYTHONPATH "$venv/bin/python" -c '
import benchdragon as bd
t = bd.collide(bd.Scenario()).time
assert f"{t:.10f}".startswith("412.4738376821"), t
print(f"test-python: pip-installed benchdragon from {bd.__file__}: Q2 at t = {t:.10f} s")')
