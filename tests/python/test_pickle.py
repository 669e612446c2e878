"""Simulations, answers, frames and pictures pickle: a round trip gives an equal object of the
same type, which works as the original does (they cross to other processes as sweeps' rows do)."""

import pickle

import numpy as np
import pytest

import benchdragon as bd


def round_trip(x):
    y = pickle.loads(pickle.dumps(x))
    assert type(y) is type(x)
    assert y == x
    return y


def test_a_simulation_pickles_and_simulates_as_before():
    sim = bd.Simulation(bd.Scenario(pitch=0.5, bench_count=60), path="turnaround")
    copy = round_trip(sim)
    assert copy.scenario == sim.scenario and copy.path == sim.path
    assert copy != bd.Simulation(bd.Scenario(pitch=0.5, bench_count=60))  # the path counts
    np.testing.assert_array_equal(copy.frames([0.0, 5.0]).positions, sim.frames([0.0, 5.0]).positions)
    assert copy.valid_range == sim.valid_range
    round_trip(sim.valid_range)


def test_frames_pickle():
    sim = bd.Simulation()
    frame = round_trip(sim.frame(100.0))
    assert frame != sim.frame(101.0)
    frames = round_trip(sim.frames(range(0, 50, 7)))
    assert len(frames) == 8


@pytest.mark.parametrize("ask", [
    lambda: bd.collide(bd.Scenario(bench_count=60)),
    lambda: bd.min_pitch(bd.Scenario(bench_count=30), grid=0.02, progress=False),
    lambda: bd.turnaround(bd.Scenario(bench_count=30), clearance=False, progress=False),
    lambda: bd.max_speed(bd.Scenario(bench_count=30)),
], ids=["collide", "min_pitch", "turnaround", "max_speed"])
def test_answers_pickle(ask):
    answer = ask()
    copy = round_trip(answer)
    assert copy.to_dict() == answer.to_dict()
    if isinstance(answer, bd.CollideResult):  # its moment rides along (not a --json key)
        assert answer.frame is not None and copy.frame == answer.frame


@pytest.mark.parametrize("format", ["png", "svg"])
def test_a_picture_pickles_with_its_pixels(format):
    pic = bd.render(bd.Scenario(pitch=0.6), t=20, format=format, size=(64, 48), speed_colours=True)
    copy = round_trip(pic)
    assert copy.data == pic.data and copy.size == pic.size and copy.time == pic.time
    np.testing.assert_array_equal(copy.to_numpy(), pic.to_numpy())
    assert copy != bd.render(bd.Scenario(pitch=0.6), t=21, format=format, size=(64, 48), speed_colours=True)
