"""Scenarios as values, and the errors with their fields, as the tool refuses the same input."""

import os
import pickle
import warnings

import pytest

import benchdragon as bd


def test_scenario_is_a_value():
    a = bd.Scenario(pitch=0.5)
    assert a == bd.Scenario(pitch=0.5) and hash(a) == hash(bd.Scenario(pitch=0.5))
    assert a != bd.Scenario()
    assert pickle.loads(pickle.dumps(a)) == a
    assert a.replace(speed=2.0).speed == 2.0 and a.speed == 1.0
    assert a.to_dict()["pitch"] == 0.5
    with pytest.raises(AttributeError):
        a.pitch = 0.6


def test_scenario_from_toml_is_the_tools(tmp_path, dragon_json):
    f = tmp_path / "s.toml"
    f.write_text("pitch = 0.6\nbench_count = 80\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # today's names: no warning
        s = bd.Scenario.from_toml(f)
    assert s.pitch == 0.6 and s.bench_count == 80
    assert bd.collide(s).to_dict() == dragon_json("collide", "--scenario", str(f))


def test_old_toml_names_warn_once_each_naming_the_key(tmp_path, dragon):
    old = tmp_path / "old.toml"
    old.write_text("[path]\nkind = \"turnaround\"\npitch = 0.6\n[motion]\nhead_speed = 2\n")
    today = tmp_path / "today.toml"
    today.write_text("path = \"turnaround\"\npitch = 0.6\nspeed = 2\n")
    with pytest.warns(FutureWarning) as caught:
        s = bd.Scenario.from_toml(old)
    assert s == bd.Scenario.from_toml(today) and s.speed == 2.0
    messages = [str(w.message) for w in caught]
    assert len(messages) == 3, messages
    assert f"scenario file '{old}': [motion] head_speed is an old name: write speed = 2 at the top level" in messages
    assert any("[path] kind is an old name: write path = \"turnaround\"" in m for m in messages)
    # The tool says the same words, one warning line each.
    done = dragon("collide", "--json", "--scenario", str(old))
    assert sorted(done.stderr.splitlines()) == sorted("dragon: warning: " + m for m in messages)
    # A key in both forms is refused, naming both.
    both = tmp_path / "both.toml"
    both.write_text("speed = 1\n[motion]\nhead_speed = 2\n")
    with pytest.raises(bd.InputError) as e:
        bd.Scenario.from_toml(both)
    assert "speed and [motion] head_speed both set" in str(e.value)
    assert e.value.field == "speed"


def test_a_storyboards_old_scenario_file_warns(tmp_path):
    (tmp_path / "old.toml").write_text("[path]\npitch = 0.6\n")
    board = tmp_path / "story.toml"
    board.write_text("[film]\nsize = \"96x64\"\nscenario = \"old.toml\"\n[[shot]]\nfrom = 10\nto = 11\nrate = 2\n")
    with pytest.warns(FutureWarning, match=r"\[path\] pitch is an old name: write pitch = 0.6") as caught:
        bd.film(board, tmp_path / "p.png", at=0.2, progress=False)
    assert len(caught) == 1
    assert (tmp_path / "p.png").exists()


@pytest.mark.parametrize("values,field", [
    ({"pitch": 0.0}, "pitch"),
    ({"speed": -1.0}, "speed"),
    ({"bench_count": 0}, "bench_count"),
    ({"width": float("nan")}, "width"),
])
def test_bad_values_name_their_keyword(values, field, dragon):
    with pytest.raises(bd.InputError) as e:
        bd.Scenario(**values)
    assert isinstance(e.value, ValueError)
    assert e.value.field == field
    assert e.value.allowed
    # The tool refuses the same value: exit 2, one line, the same reason.
    flag = "--" + field.replace("_", "-")
    done = dragon("collide", flag, str(list(values.values())[0]), check=False)
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and e.value.allowed in done.stderr


def test_unknown_keyword():
    # As any Python call with a keyword it does not take.
    with pytest.raises(TypeError) as e:
        bd.Scenario(pich=0.5)
    assert "pich" in str(e.value)


def test_a_moment_past_the_valid_motion_carries_the_jam():
    sim = bd.Simulation()
    end = sim.valid_range.to
    with pytest.raises(bd.InputError) as e:
        sim.frame(end + 1.0)
    jam = e.value.jam
    assert jam is not None and jam.handle == 1 and jam.time == pytest.approx(end, abs=1e-9)
    sim.frame(end)  # the last valid moment itself is drawn


def test_error_kinds(tmp_path):
    # A file named that is not there is bad input, as the tool's exit code 2 says; a file that
    # cannot be written is a FileError (an OSError).
    with pytest.raises(bd.InputError) as e:
        bd.Scenario.from_toml(tmp_path / "missing.toml")
    assert "does not exist" in str(e.value)
    assert issubclass(bd.FileError, OSError)
    assert issubclass(bd.SolverError, RuntimeError)


def test_an_unwritable_output_is_a_file_error_and_leaves_nothing(tmp_path):
    if os.geteuid() == 0:
        pytest.skip("root writes into read-only folders")
    d = tmp_path / "ro"
    d.mkdir()
    d.chmod(0o500)
    try:
        with pytest.raises(bd.FileError):
            bd.render(t=10, size=(64, 64)).save(d / "x.png")
        assert list(d.iterdir()) == []
    finally:
        d.chmod(0o700)


def test_windows_and_options_refused_by_name():
    with pytest.raises(bd.InputError) as e:
        bd.collide(bd.Scenario(), from_="ten metres")
    assert e.value.field == "from_"
    with pytest.raises(bd.InputError) as e:
        bd.min_pitch(bd.Scenario(), grid=-1, progress=False)
    assert e.value.field == "grid"
    with pytest.raises(bd.InputError) as e:
        bd.Simulation(path="zigzag")
    assert e.value.field == "path"
