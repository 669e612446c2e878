"""The library keeps no state behind its caller's back: a forked worker (concurrent.futures'
ProcessPoolExecutor, Linux's default start) computes after its parent did, and answers what the
parent answers. And a Scenario refuses a value when it is made, naming its keyword."""
import concurrent.futures
import json
import os
import subprocess
import multiprocessing
import sys

import pytest

import benchdragon as bd


def _work(kind):
    if kind == "collide":
        return bd.collide()["time"]
    if kind == "min_pitch":
        return bd.min_pitch(lo=0.44, hi=0.46, progress=False)["pitch"]
    frames = bd.Simulation(bd.Scenario()).frames([0.0, 100.0, 300.0])
    return float(frames.positions[-1][0][0]), float(frames.speeds[-1][-1])


@pytest.mark.skipif(sys.platform != "linux", reason="fork is the default start on Linux")
def test_a_forked_worker_computes_after_its_parent():
    # The parent uses the library first: a pool made behind its back would be inherited broken.
    expected = {k: _work(k) for k in ("collide", "min_pitch", "frames")}
    with concurrent.futures.ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("fork")) as pool:
        futures = {k: pool.submit(_work, k) for k in expected}
        got = {k: f.result(timeout=120) for k, f in futures.items()}  # a hang fails here, not for ever
    assert got == expected


def test_a_scenario_refuses_a_value_when_it_is_made():
    with pytest.raises(bd.InputError) as e:
        bd.Scenario(hole_offset=5)
    assert e.value.field == "hole_offset"
    with pytest.raises(bd.InputError) as e:
        bd.Scenario(bench_count=2**31)
    assert e.value.field == "bench_count"
    assert e.value.value == str(2**31)  # as given, not narrowed to -2147483648
    for flag in (True, False):
        with pytest.raises(bd.InputError) as e:
            bd.Scenario(bench_count=flag)
        assert e.value.field == "bench_count"
    with pytest.raises(bd.InputError) as e:
        bd.Scenario(pitch=True)
    assert e.value.field == "pitch"
    with pytest.raises(bd.InputError) as e:
        bd.Scenario(speed=0)
    assert e.value.field == "speed"
    assert bd.Scenario(bench_count=10).bench_count == 10


def test_min_pitch_follows_the_width_as_the_tool_does():
    # The contest's 0.35 .. 0.55 m would put the turns closer than 0.35 m benches: the range moves
    # up, in Python as in the tool (which refused it before), to the same answer.
    r = bd.min_pitch(bd.Scenario(width=0.35), progress=False)
    assert r["pitch"] is not None and r["pitch"] > 0.35
    tool = os.environ.get("DRAGON_BIN")
    if not tool:
        pytest.skip("DRAGON_BIN is not set (scripts/test-python.sh sets it)")
    done = subprocess.run([tool, "min-pitch", "--width", "0.35", "--json"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["pitch"] == r["pitch"]


def test_workers_choose_the_threads_not_the_answer():
    one = bd.min_pitch(lo=0.44, hi=0.46, progress=False, workers=1)
    two = bd.min_pitch(lo=0.44, hi=0.46, progress=False, workers=2)
    assert one.to_dict() == two.to_dict() or one["pitch"] == two["pitch"]
    assert bd.collide(workers=1)["time"] == bd.collide(workers=2)["time"]
    with pytest.raises(bd.InputError) as e:
        bd.collide(workers=-1)
    assert e.value.field == "workers"


@pytest.mark.parametrize("call", [
    lambda w: bd.turnaround(to="20m", progress=False, workers=w).to_dict(),
    lambda w: bd.max_speed(from_="-20m", to="20m", workers=w).to_dict(),
    lambda w: bd.solve(only=[2], workers=w).to_dict(),
    lambda w: bd.Simulation().frames([0.0, 100.0, 300.5], workers=w).positions.tolist(),
], ids=["turnaround", "max_speed", "solve", "frames"])
def test_every_parallel_call_takes_workers_and_gives_one_answer(call):
    assert call(1) == call(2) == call(0)
    for bad in (-1, 1025, True, 1.5):
        with pytest.raises(bd.InputError) as e:
            call(bad)
        assert e.value.field == "workers"


def test_films_take_workers(tmp_path):
    one = bd.video(out=str(tmp_path / "a.gif"), to=1, size=(64, 48), progress=False, workers=1)
    two = bd.video(out=str(tmp_path / "b.gif"), to=1, size=(64, 48), progress=False, workers=2)
    assert one["frames"] == two["frames"]
    assert (tmp_path / "a.gif").read_bytes() == (tmp_path / "b.gif").read_bytes()
    with pytest.raises(bd.InputError) as e:
        bd.film(os.path.join(bd.ASSETS, "films", "contest.toml"), str(tmp_path / "c.png"), at=1.0, workers=-1)
    assert e.value.field == "workers"
