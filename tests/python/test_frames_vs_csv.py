"""Frames as numpy arrays hold what the tool's CSV holds, to every digit it prints."""

import io
import math

import numpy as np
import pandas as pd
import pytest

import benchdragon as bd


def table_number(v: float, digits: int) -> str:
    """v with `digits` decimals by the tables' rule: v * 10^digits rounded to an integer (halves
    away from zero) while that product is below 2^52, else v's correctly rounded expansion;
    never "-0.000"."""
    scale = 10.0 ** digits
    if abs(v * scale) < 2.0 ** 52:
        x = abs(v * scale)
        whole = math.floor(x)
        v = math.copysign(whole + (1.0 if x - whole >= 0.5 else 0.0), v) / scale
    out = f"{v:.{digits}f}"
    return out[1:] if out.startswith("-") and not out.strip("-0.") else out


@pytest.mark.parametrize("path,flags,times", [
    ("spiral", [], np.arange(0.0, 301.0, 25.0)),
    ("turnaround", ["--path", "turnaround", "--from", "-100", "--to", "100", "--step", "20"],
     np.arange(-100.0, 101.0, 20.0)),
])
def test_arrays_equal_the_csv(dragon, path, flags, times):
    if path == "spiral":
        flags = ["--from", "0", "--to", "300", "--step", "25"]
    out = dragon("simulate", *flags, "--digits", "17", "--quiet").stdout
    csv = pd.read_csv(io.StringIO(out), float_precision="round_trip")
    sim = bd.Simulation(bd.Scenario(), path=path)
    f = sim.frames(times)
    assert f.positions.shape == (len(times), 224, 2)
    assert f.speeds.shape == (len(times), 224)
    assert f.positions.dtype == np.float64
    np.testing.assert_array_equal(np.unique(csv["t"].to_numpy()), times)
    # Each number as the tool's tables print it (their documented rule, tables.hpp): the same
    # text, digit for digit.
    text = pd.read_csv(io.StringIO(out), dtype=str)
    for column, values in (("x", f.positions[:, :, 0]), ("y", f.positions[:, :, 1]), ("speed", f.speeds)):
        assert [table_number(v, 17) for v in values.ravel()] == list(text[column]), column
    # to_pandas is the CSV's layout.
    frame = sim.to_pandas(times)
    assert list(frame.columns) == ["t", "handle", "x", "y", "speed"]
    np.testing.assert_array_equal(frame["x"].to_numpy(), f.positions[:, :, 0].ravel())


def test_frame_and_frames_agree():
    sim = bd.Simulation()
    one = sim.frame(123.25)
    many = sim.frames([123.25])
    np.testing.assert_array_equal(one.positions, many.positions[0])
    np.testing.assert_array_equal(one.speeds, many.speeds[0])
