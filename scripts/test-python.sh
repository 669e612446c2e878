#!/usr/bin/env bash
# The Python package's tests, on the build that scripts/build.sh made: pytest (every call against
# the tool, arrays against its CSV, errors, sweeps on threads, processes and Dask, Ctrl-C,
# properties with hypothesis); the example notebook executed headless, with no error in any
# output; and `pip install .` offline into a fresh venv from that build, imported from outside
# the source tree. Skips, saying why, when the build has no Python package.
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

# The notebook, run where it may write its film (a copy in build/), then checked for errors that
# nbconvert lets pass (a failed display is an output, not a failed cell).
rm -rf build/notebook && mkdir -p build/notebook
cp examples/python/contest.ipynb build/notebook/
# (PYDEVD_DISABLE_FILE_VALIDATION: the kernel's debugger would warn about frozen modules.)
BENCHDRAGON_HEADLESS=1 PYDEVD_DISABLE_FILE_VALIDATION=1 "$py" -m nbconvert --to notebook --execute \
  build/notebook/contest.ipynb --inplace --ExecutePreprocessor.timeout=600
"$py" - <<'PY'
import nbformat
nb = nbformat.read("build/notebook/contest.ipynb", as_version=4)
errors = [o for c in nb.cells for o in c.get("outputs", []) if o.output_type == "error"]
unrun = [c for c in nb.cells if c.cell_type == "code" and c.execution_count is None]
if errors or unrun:
    raise SystemExit(f"test-python: the notebook has {len(errors)} error outputs and {len(unrun)} cells not run")
print(f"test-python: the notebook ran, {sum(c.cell_type == 'code' for c in nb.cells)} cells, no errors")
PY

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
