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


def test_frames_as_xarray_hold_the_arrays_units_and_scenario():
    xr = pytest.importorskip("xarray", reason="python3-xarray is not installed")
    sc = bd.Scenario(pitch=0.6)
    sim = bd.Simulation(sc)
    times = [0.0, 10.0, 20.5]
    f = sim.frames(times)
    ds = f.to_xarray()
    assert isinstance(ds, xr.Dataset)
    assert ds["position"].dims == ("time", "handle", "coordinate")
    assert ds["speed"].dims == ("time", "handle")
    assert ds.sizes == {"time": 3, "handle": 224, "coordinate": 2}
    assert list(ds["coordinate"].values) == ["x", "y"]
    np.testing.assert_array_equal(ds["time"].values, times)
    np.testing.assert_array_equal(ds["handle"].values, np.arange(224))
    # The same numbers as the arrays, and as one frame computed on its own.
    np.testing.assert_array_equal(ds["position"].values, f.positions)
    one = sim.frame(10.0)
    np.testing.assert_array_equal(ds["position"].sel(time=10.0).values, one.positions)
    np.testing.assert_array_equal(ds["speed"].sel(time=10.0).values, one.speeds)
    assert ds["position"].attrs["units"] == "m"
    assert ds["speed"].attrs["units"] == "m/s"
    assert ds["time"].attrs["units"] == "s"
    assert ds.attrs["path"] == "spiral"
    assert ds.attrs["scenario_pitch"] == 0.6
    assert ds.attrs["scenario_bench_count"] == 223
    # x of handle 0 at t = 0 is where the head starts: 16 turns out at this pitch.
    assert ds["position"].sel(time=0.0, handle=0, coordinate="x").item() == pytest.approx(16 * 0.6)


def test_frames_to_netcdf_and_back(tmp_path):
    pytest.importorskip("xarray", reason="python3-xarray is not installed")
    pytest.importorskip("netCDF4", reason="python3-netcdf4 is not installed")
    import xarray as xr

    sim = bd.Simulation(bd.Scenario(), path="turnaround")
    ds = sim.frames(np.arange(-100.0, 101.0, 50.0)).to_xarray()
    path = tmp_path / "turn.nc"
    ds.to_netcdf(path, engine="netcdf4")
    back = xr.load_dataset(path, engine="netcdf4")
    np.testing.assert_array_equal(back["position"].values, ds["position"].values)
    np.testing.assert_array_equal(back["speed"].values, ds["speed"].values)
    assert back["speed"].attrs["units"] == "m/s"
    assert back.attrs["path"] == "turnaround"
    assert back.attrs["scenario_turn_pitch"] == 1.7
