"""The example notebook runs as a user runs it: `jupyter nbconvert --to notebook --execute`, no
variable set, every cell run with no error, and the slider's cell showing the dragon (the
slider where a widget front end can show it, one moment drawn where none can)."""

import base64
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

NOTEBOOK = Path(__file__).resolve().parents[2] / "examples" / "python" / "contest.ipynb"


def test_the_notebook_runs_under_nbconvert(tmp_path):
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed (Debian: python3-nbformat)")
    try:
        import nbconvert  # noqa: F401
    except ImportError:
        pytest.skip("nbconvert is not installed (Debian: jupyter-nbconvert)")
    pytest.importorskip("ipykernel", reason="no Jupyter kernel for Python (Debian: python3-ipykernel)")
    # A copy where it may write its film (coil.gif beside it).
    shutil.copy(NOTEBOOK, tmp_path / "contest.ipynb")
    done = subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute", "contest.ipynb",
                           "--output", "ran.ipynb", "--ExecutePreprocessor.timeout=600"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr[-3000:]
    nb = nbformat.read(tmp_path / "ran.ipynb", as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    errors = [o for c in code for o in c.outputs if o.output_type == "error"]
    assert not errors, [f"{e.ename}: {e.evalue}" for e in errors]
    assert all(c.execution_count is not None for c in code)
    # The last cell, the slider's: a widget, or a picture of the dragon (a PNG that decodes).
    shown = [o for o in code[-1].outputs if o.output_type in ("display_data", "execute_result")]
    assert shown, code[-1].outputs
    data = shown[0].data
    if "application/vnd.jupyter.widget-view+json" not in data:
        png = base64.b64decode(data["image/png"])
        assert png[:8] == b"\x89PNG\r\n\x1a\n"
