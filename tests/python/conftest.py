"""Shared fixtures: the dragon tool the package is checked against, and scratch folders.

The package under test is the one on sys.path (PYTHONPATH=build/python, or an installed one);
the tool is $DRAGON_BIN, or build/src/dragon beside this checkout.
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _dragon_path() -> Path:
    given = os.environ.get("DRAGON_BIN")
    return Path(given) if given else ROOT / "build" / "src" / "dragon"


@pytest.fixture(scope="session")
def dragon_exe() -> Path:
    """The tool's path, for a test that starts it itself (to kill it)."""
    exe = _dragon_path()
    if not exe.exists():
        pytest.skip(f"the dragon tool is not built at {exe} (set DRAGON_BIN)")
    return exe


@pytest.fixture(scope="session")
def dragon(dragon_exe):
    """Runs the tool; returns its CompletedProcess (text)."""
    exe = dragon_exe

    def run(*args: str, check: bool = True) -> subprocess.CompletedProcess:
        done = subprocess.run([str(exe), *args], capture_output=True, text=True, timeout=600)
        if check and done.returncode != 0:
            raise AssertionError(f"dragon {' '.join(args)} failed ({done.returncode}): {done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def dragon_json(dragon):
    """The tool's --json answer for a command, parsed."""

    def run(*args: str) -> dict:
        return json.loads(dragon(*args, "--json", "--quiet").stdout)

    return run
