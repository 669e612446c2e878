"""prove=True: what collide and max_speed proved, said as the tool's --prove --json says it, and
what it proves holding the answer found without it."""

import pytest

import benchdragon as bd

# (keywords, the tool's flags): a contact on the spiral, on the turnaround path, and none.
COLLIDE_CASES = [
    ({}, []),
    ({"path": "turnaround", "from_": "-50m", "to": 30}, ["--path", "turnaround", "--from", "-50m", "--to", "30"]),
    ({"from_": 0, "to": "100m"}, ["--from", "0", "--to", "100m"]),
]
COLLIDE_SCENARIOS = [bd.Scenario(), bd.Scenario(turn_pitch=0.44), bd.Scenario()]
COLLIDE_FLAGS = [[], ["--turn-pitch", "0.44"], []]


@pytest.mark.parametrize("case", range(len(COLLIDE_CASES)))
def test_collide_proof_is_the_tools(dragon_json, case):
    keywords, flags = COLLIDE_CASES[case]
    mine = bd.collide(COLLIDE_SCENARIOS[case], prove=True, **keywords).to_dict()
    tool = dragon_json("collide", "--prove", *COLLIDE_FLAGS[case], *flags)
    assert mine["enclosure"] == tool["enclosure"]
    assert mine["proof"] == tool["proof"]
    assert mine == tool
    # Asked to prove, every step was (the method says so), and the steps cover the window up to
    # the contact, or all of it without one.
    assert mine["proof"]["method"] in ("enclosure", "enclosure+rate")
    assert mine["proof"]["steps"] > 0
    covered = mine["proof"]["covered_travel"]
    assert covered[0] == mine["from_travel"]
    if mine["travel"] is None:
        assert mine["enclosure"] is None
        assert covered[1] == mine["to_travel"]
    else:
        assert covered[1] == mine["enclosure"]["travel"][0]


@pytest.mark.parametrize("case", range(len(COLLIDE_CASES)))
def test_collide_proved_enclosure_holds_the_unproved_contact(case):
    keywords, _ = COLLIDE_CASES[case]
    s = COLLIDE_SCENARIOS[case]
    proved = bd.collide(s, prove=True, **keywords)
    sampled = bd.collide(s, **keywords)
    assert sampled.proof["method"] == "rate" and sampled.proof["steps"] == 0
    assert (proved.travel is None) == (sampled.travel is None)
    if proved.travel is None:
        return
    assert proved.benches == sampled.benches
    # The first contact lies in the enclosure; the unproved search's contact is a moment the
    # benches touch, at most its own tolerance (s, so tolerance * speed m of head travel) past
    # the first contact: at or after the enclosure's low end, and within that of its high end.
    lo, hi = proved.enclosure["travel"]
    assert lo <= hi
    assert lo <= sampled.travel <= hi + sampled.tolerance * s.speed
    t_lo, t_hi = proved.enclosure["time"]
    assert t_lo <= sampled.time <= t_hi + sampled.tolerance
    assert hi == proved.travel and t_hi == proved.time


MAX_SPEED_CASES = [
    (bd.Scenario(), {}, []),
    (bd.Scenario(turn_radius=4.0, arc_ratio=1.5), {"limit": 1.8, "from_": -20, "to": "40m"},
     ["--turn-radius", "4", "--arc-ratio", "1.5", "--limit", "1.8", "--from", "-20", "--to", "40m"]),
]


@pytest.mark.parametrize("case", range(len(MAX_SPEED_CASES)))
def test_max_speed_proof_is_the_tools(dragon_json, case):
    s, keywords, flags = MAX_SPEED_CASES[case]
    mine = bd.max_speed(s, prove=True, **keywords).to_dict()
    tool = dragon_json("max-speed", "--prove", *flags)
    assert mine["enclosure"] == tool["enclosure"]
    assert mine["proof"] == tool["proof"]
    assert mine == tool
    assert mine["proof"]["method"] == "lipschitz bound"


@pytest.mark.parametrize("case", range(len(MAX_SPEED_CASES)))
def test_max_speed_proved_enclosure_holds_the_sampled_maximum(case):
    s, keywords, _ = MAX_SPEED_CASES[case]
    proved = bd.max_speed(s, prove=True, **keywords)
    sampled = bd.max_speed(s, **keywords)
    assert sampled.enclosure is None and sampled.proof == {"method": "sampled"}
    lo, hi = proved.enclosure
    assert lo <= sampled.max_head_speed <= hi
    assert lo <= proved.max_head_speed <= hi
    # The ratio's enclosure, the same claim seen from the handles: limit / ratio.
    r_lo, r_hi = proved.proof["ratio"]
    assert r_lo <= sampled.ratio <= r_hi


@pytest.mark.parametrize("value", ["yes", 1, 0, None, 1.0])
def test_a_bad_prove_is_refused_naming_it(value):
    for call in (lambda: bd.collide(prove=value), lambda: bd.max_speed(prove=value)):
        with pytest.raises(bd.InputError) as e:
            call()
        assert e.value.field == "prove"
        assert e.value.value == repr(value)
        assert e.value.allowed == "give True or False"
        assert str(e.value) == f"prove {value!r} is not allowed: give True or False"


def test_min_pitch_proof_is_the_tools(dragon_json):
    # A range about the contest's cut, so that the proof runs in a second or so.
    mine = bd.min_pitch(lo=0.44, hi=0.47, grid=0.01, prove=True, progress=False).to_dict()
    tool = dragon_json("min-pitch", "--prove", "--lo", "0.44", "--hi", "0.47", "--grid", "0.01")
    assert mine == tool
    proof = mine["proof"]
    assert proof["method"].startswith("enclosure cells")
    # What it proved lies inside the feasible intervals; the rest of them is what it did not.
    feasible = [(i["lo"], i["hi"]) for i in mine["intervals"] if i["feasible"]]
    for lo, hi in proof["proved"] + proof["unproved"]:
        assert any(a <= lo and hi <= b for a, b in feasible)
    width = sum(hi - lo for lo, hi in proof["proved"] + proof["unproved"])
    assert width == pytest.approx(sum(b - a for a, b in feasible), abs=1e-12)
    # Only the pitches next to the cut are left to the runs.
    assert sum(hi - lo for lo, hi in proof["unproved"]) < 1e-6
    # The least feasible pitch is bracketed around the one the search found.
    lo, hi = proof["least_feasible"]
    assert lo <= mine["pitch"] <= hi and hi - lo < 1e-5
    unproved = bd.min_pitch(lo=0.44, hi=0.47, grid=0.01, progress=False).to_dict()
    assert unproved["proof"]["method"] == "runs" and unproved["proof"]["unproved"] is None
    assert unproved["pitch"] == mine["pitch"]


def test_turnaround_proof_is_the_tools(dragon_json):
    mine = bd.turnaround(prove=True, progress=False).to_dict()
    tool = dragon_json("turnaround", "--prove")
    assert mine["proof"] == tool["proof"] and mine["enclosure"] == tool["enclosure"]
    assert mine["proof"]["method"] == "enclosure"
    assert mine["proof"]["covered_travel"] == [mine["clearance"]["from_travel"], mine["clearance"]["to_travel"]]
    # The smallest clearance enclosed: proved at least `at_least`, found at `distance`, 1e-6 m apart.
    least = mine["proof"]["clearance"]
    assert least["proved"] and 0 < mine["clearance"]["distance"] - least["at_least"] <= 1.0001e-6
    assert bd.turnaround(progress=False).to_dict()["proof"]["clearance"] is None
    with pytest.raises(bd.InputError) as e:
        bd.turnaround(prove=True, clearance=False, progress=False)
    assert e.value.field == "prove"


def test_solve_proves_what_the_single_commands_prove(dragon, dragon_json, tmp_path):
    # dragon solve --prove writes the same summary as solve(prove=True), and each proof is the one
    # its own command proves (Q4's check is turnaround's first-contact proof over the same window).
    import json

    dragon("solve", "--prove", "--only", "q2,q4,q5", "--out", str(tmp_path), "--quiet")
    written = json.loads((tmp_path / "summary.json").read_text())
    mine = bd.solve(only=[2, 4, 5], prove=True).to_dict()
    assert mine == written
    collide = dragon_json("collide", "--prove")
    assert mine["q2"]["proof"] == collide["proof"] and mine["q2"]["enclosure"] == collide["enclosure"]
    assert mine["q5"]["proof"] == dragon_json("max-speed", "--prove")["proof"]
    turn = dragon_json("turnaround", "--prove")["proof"]
    turn.pop("clearance")  # the turnaround's own: its least clearance, which solve does not look for
    assert mine["q4"]["proof"] == turn
    assert "proof" not in bd.solve(only=[4]).to_dict()["q4"]
