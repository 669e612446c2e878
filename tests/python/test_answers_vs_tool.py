"""Every answer's to_dict() equals json.loads of the tool's --json for the same scenario: the
library builds each answer once, and the tool and the package both print it."""

import pytest

import benchdragon as bd

# Scenarios unlike the contest's in each direction the answers depend on, as flags and keywords.
SCENARIOS = [
    ({}, []),
    ({"pitch": 0.5, "speed": 2.0}, ["--pitch", "0.5", "--speed", "2"]),
    ({"bench_count": 60, "body_length": 1.8, "width": 0.25}, ["--bench-count", "60", "--body-length", "1.8",
                                                              "--width", "0.25"]),
    ({"turn_radius": 4.0, "turn_pitch": 1.5, "arc_ratio": 1.5, "speed": 0.5},
     ["--turn-radius", "4", "--turn-pitch", "1.5", "--arc-ratio", "1.5", "--speed", "0.5"]),
]


def without(flags, *names):
    out = list(flags)
    for name in names:
        while name in out:
            k = out.index(name)
            del out[k:k + 2]
    return out


def turn_flags(flags):
    """The flags the turnaround path reads (the tool refuses a value a command does not read)."""
    return without(flags, "--pitch")


def spiral_flags(flags):
    """The flags collide on the plain spiral reads."""
    return without(flags, "--turn-radius", "--turn-pitch", "--arc-ratio")


@pytest.mark.parametrize("values,flags", SCENARIOS)
def test_collide_on_both_paths(dragon_json, values, flags):
    s = bd.Scenario(**values)
    assert bd.collide(s).to_dict() == dragon_json("collide", *spiral_flags(flags))
    assert bd.collide(s, path="turnaround").to_dict() == dragon_json("collide", "--path", "turnaround", *turn_flags(flags))


@pytest.mark.parametrize("values,flags", SCENARIOS)
def test_turnaround_and_max_speed(dragon_json, values, flags):
    s = bd.Scenario(**values)
    assert bd.turnaround(s, progress=False).to_dict() == dragon_json("turnaround", *turn_flags(flags))
    assert bd.max_speed(s).to_dict() == dragon_json("max-speed", *turn_flags(flags))


def test_windows_given_both_ways(dragon_json):
    s = bd.Scenario(turn_pitch=0.44)
    assert bd.collide(s, path="turnaround", from_="-50m", to=30).to_dict() == dragon_json(
        "collide", "--path", "turnaround", "--turn-pitch", "0.44", "--from", "-50m", "--to", "30")
    assert bd.max_speed(bd.Scenario(), limit=1.8, from_=-20, to="40m").to_dict() == dragon_json(
        "max-speed", "--limit", "1.8", "--from", "-20", "--to", "40m")


@pytest.mark.parametrize("values,flags", SCENARIOS[:3])
def test_min_pitch(dragon_json, values, flags):
    s = bd.Scenario(**values)
    assert bd.min_pitch(s, lo=0.4, hi=0.55, grid=0.005, progress=False).to_dict() == dragon_json(
        "min-pitch", "--lo", "0.4", "--hi", "0.55", "--grid", "0.005", *without(flags, "--pitch"))


def test_solve_is_the_summary_the_tool_writes(dragon, tmp_path):
    out = tmp_path / "tool"
    dragon("solve", "--out", str(out), "--quiet")
    import json

    written = json.loads((out / "summary.json").read_text())
    mine = bd.solve(out=tmp_path / "py")
    assert mine.to_dict() == written
    assert json.loads((tmp_path / "py" / "summary.json").read_text()) == written
    for name in ("result1.xlsx", "result2.xlsx", "result4.xlsx"):
        assert (tmp_path / "py" / name).stat().st_size > 0


def test_the_contest_answer_to_the_last_digit():
    # PROBLEM.md's Q2: the head's first contact at 412.4738376821... s (benches 1 and 9).
    r = bd.collide(bd.Scenario())
    assert f"{r.time:.10f}".startswith("412.4738376821")
    assert r.benches == [1, 9]


def test_concurrent_calls_from_threads_answer_as_alone():
    from concurrent.futures import ThreadPoolExecutor

    scenarios = [bd.Scenario(pitch=p) for p in (0.5, 0.55, 0.6, 0.65)]
    alone = [bd.collide(s).to_dict() for s in scenarios]
    sim = bd.Simulation()
    with ThreadPoolExecutor(max_workers=4) as ex:
        together = list(ex.map(lambda s: bd.collide(s).to_dict(), scenarios * 2))
        frames = list(ex.map(lambda t: sim.frame(t).positions, [10.0, 200.0] * 4))
    assert together == alone * 2
    for k, f in enumerate(frames):
        assert (f == sim.frame([10.0, 200.0][k % 2]).positions).all()
