"""Sweeps: the same rows on any executor (threads, processes, a Dask cluster) as the tool's."""

import io
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pandas as pd
import pytest

import benchdragon as bd
from serial_executor import Serial

VARY = {"pitch": "0.45:0.6:4", "bench_count": [40, 120]}
FLAGS = ["--vary", "pitch=0.45:0.6:4", "--vary", "bench-count=40,120"]


def tool_rows(text: str, by: list) -> pd.DataFrame:
    """The tool's sweep CSV (its first line the sweep's own description), in the grid's order
    (the tool writes each row as it finishes)."""
    assert text.startswith("# dragon sweep ")
    rows = pd.read_csv(io.StringIO(text.split("\n", 1)[1]))
    return rows.sort_values(by, kind="stable").reset_index(drop=True)


@pytest.fixture(scope="module")
def serial():
    return bd.sweep(VARY, "collide", executor=Serial(), chunk=3, progress=False)


def test_rows_are_the_tools(dragon, serial):
    out = dragon("sweep", *FLAGS, "--measure", "collide", "--quiet").stdout
    tool = tool_rows(out, ["pitch", "bench-count"])
    mine = serial.sort_values(["pitch", "bench-count"], kind="stable").reset_index(drop=True)
    pd.testing.assert_frame_equal(mine, tool)
    assert serial.attrs["sweep"] == out.split("\n", 1)[0][len("# dragon sweep "):]
    assert len(serial) == 8 and (serial["status"] == "ok").all()


def test_threads_and_processes_equal_serial(serial):
    with ThreadPoolExecutor(max_workers=2) as ex:
        pd.testing.assert_frame_equal(bd.sweep(VARY, "collide", executor=ex, progress=False), serial)
    with ProcessPoolExecutor(max_workers=2) as ex:
        pd.testing.assert_frame_equal(
            bd.sweep(VARY, "collide", executor=ex, chunk=2, progress=False), serial)


def test_a_dask_cluster_equals_serial(serial):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=50) as cluster, distributed.Client(cluster) as client:
        pd.testing.assert_frame_equal(
            bd.sweep(VARY, "collide", executor=client, chunk=2, progress=False), serial)


def test_fixed_values_and_options_reach_every_row(dragon):
    rows = bd.sweep({"turn_pitch": [1.5, 1.7]}, "turnaround", fixed={"turn_radius": 4.2}, to="50m",
                    progress=False)
    tool = tool_rows(dragon("sweep", "--vary", "turn-pitch=1.5,1.7", "--measure", "turnaround", "--turn-radius",
                            "4.2", "--to", "50m", "--quiet").stdout, ["turn-pitch"])
    pd.testing.assert_frame_equal(rows, tool)


def test_progress_hears_every_row():
    heard = []
    bd.sweep({"pitch": [0.5, 0.55, 0.6]}, "collide", chunk=1, progress=lambda done, total: heard.append((done, total)))
    assert heard[-1] == (3, 3)
    assert [d for d, _ in heard] == sorted(d for d, _ in heard)


def test_bad_axes_are_refused_by_name():
    with pytest.raises(bd.InputError) as e:
        bd.sweep({"colour": [1, 2]}, "collide", progress=False)
    assert e.value.field == "vary"
    with pytest.raises(bd.InputError) as e:
        bd.sweep({"pitch": [0.5]}, "fly", progress=False)
    assert e.value.field == "measure"
