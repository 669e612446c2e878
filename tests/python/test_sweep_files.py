"""A sweep's rows files across the front ends: a sweep the tool began (and was killed in) is
finished by Python, shards are written and merged by either, and every file is byte for byte the
one the tool writes. The tool runs its rows on one worker here, so that its rows are in the
grid's order, as Python appends them."""

import os
import signal
import subprocess
import time
from pathlib import Path

import pandas as pd
import pytest

import benchdragon as bd
from serial_executor import Serial

VARY = {"pitch": "0.45:0.6:4", "bench_count": [40, 120]}
FLAGS = ["--vary", "pitch=0.45:0.6:4", "--vary", "bench-count=40,120", "--measure", "collide"]
# Turnaround rows take a tenth of a second or more each: a run of them can be killed in the middle.
SLOW_VARY = {"bench_count": "60:130:8"}
SLOW_FLAGS = ["--vary", "bench-count=60:130:8", "--measure", "turnaround"]


def rows_in(path: Path) -> int:
    """The complete rows a rows' file holds (its first two lines aside)."""
    return max(0, path.read_bytes().count(b"\n") - 2) if path.exists() else 0


def tool_file(dragon, path: Path, flags: list, *more: str) -> bytes:
    dragon("sweep", *flags, "--workers", "1", "-q", "-o", str(path), *more)
    return path.read_bytes()


def test_a_sweep_the_tool_began_and_was_killed_in_is_finished_by_python(dragon, dragon_exe, tmp_path):
    whole = tool_file(dragon, tmp_path / "whole.csv", SLOW_FLAGS)
    out = tmp_path / "rows.csv"
    partial = tmp_path / "rows.csv.partial"
    tool = subprocess.Popen([str(dragon_exe), "sweep", *SLOW_FLAGS, "--workers", "1", "-q", "-o", str(out)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and rows_in(partial) < 2 and tool.poll() is None:
            time.sleep(0.005)
        tool.send_signal(signal.SIGKILL)
    finally:
        tool.wait()
    assert tool.returncode == -signal.SIGKILL, "the sweep ended before the kill"
    assert not out.exists()
    before = rows_in(partial)
    assert 2 <= before < 8
    # What a kill in the middle of a write leaves: a row cut short, without its line end.
    with open(partial, "ab") as f:
        f.write(b"95,1.3")

    # Not started afresh over the tool's rows.
    with pytest.raises(bd.InputError) as refused:
        bd.sweep(SLOW_VARY, "turnaround", out=out, executor=Serial(), progress=False)
    assert refused.value.field == "resume"
    rows = bd.sweep(SLOW_VARY, "turnaround", out=out, resume=True, executor=Serial(), chunk=1, progress=False)
    assert out.read_bytes() == whole
    assert not partial.exists()
    assert rows.attrs["resumed"] == before
    assert len(rows) == 8
    # The frame is the file's rows, in the grid's order.
    expected = pd.read_csv(tmp_path / "whole.csv", skiprows=1)
    pd.testing.assert_frame_equal(rows, expected)


def test_a_failed_row_is_made_again_and_a_finished_file_resumed_makes_nothing(dragon, tmp_path):
    whole = tool_file(dragon, tmp_path / "whole.csv", FLAGS)
    lines = whole.decode().split("\n")
    header = lines[1].split(",")
    # The second row as a failed measure writes it: its cells empty, its status saying so.
    failed = lines[3].split(",")[0] + "," + lines[3].split(",")[1] + "," * (len(header) - 3)
    failed += ",failed (collide): the search did not converge"
    out = tmp_path / "rows.csv"
    Path(str(out) + ".partial").write_text("\n".join(lines[:3] + [failed]) + "\n")
    bd.sweep(VARY, "collide", out=out, resume=True, executor=Serial(), progress=False)
    assert out.read_bytes() == whole
    # Finished: resumed, nothing is made and the bytes stay.
    again = bd.sweep(VARY, "collide", out=out, resume=True, executor=Serial(), progress=False)
    assert again.attrs["resumed"] == 8
    assert out.read_bytes() == whole


def test_pythons_file_is_the_tools_and_the_tool_resumes_it(dragon, tmp_path):
    whole = tool_file(dragon, tmp_path / "whole.csv", FLAGS)
    mine = tmp_path / "mine.csv"
    bd.sweep(VARY, "collide", out=mine, executor=Serial(), chunk=3, progress=False)
    assert mine.read_bytes() == whole
    done = dragon("sweep", *FLAGS, "--resume", "-o", str(mine))
    assert "8 of 8 rows are in" in done.stderr
    assert mine.read_bytes() == whole


def test_shards_written_by_either_and_merged_by_either_are_the_same_bytes(dragon, tmp_path):
    tool_parts = [tmp_path / "tool1.csv", tmp_path / "tool2.csv"]
    for k, part in enumerate(tool_parts, start=1):
        tool_file(dragon, part, FLAGS, "--shard", f"{k}/2")
    mine = [tmp_path / "mine1.csv", tmp_path / "mine2.csv"]
    bd.sweep(VARY, "collide", out=mine[0], shard=(1, 2), executor=Serial(), progress=False)
    bd.sweep(VARY, "collide", out=mine[1], shard="2/2", executor=Serial(), progress=False)
    for theirs, ours in zip(tool_parts, mine):
        assert ours.read_bytes() == theirs.read_bytes()

    dragon("sweep", "merge", str(tmp_path / "tool.csv"), *map(str, tool_parts), "-q")
    merged = bd.merge_sweep(tmp_path / "mine.csv", tool_parts)
    assert (tmp_path / "mine.csv").read_bytes() == (tmp_path / "tool.csv").read_bytes()
    # The merged sweep is the whole sweep's frame.
    whole = bd.sweep(VARY, "collide", executor=Serial(), progress=False)
    pd.testing.assert_frame_equal(merged, whole)
    assert merged.attrs["sweep"] == whole.attrs["sweep"]


def test_a_merge_refuses_what_is_not_the_whole_sweep_once(dragon, tmp_path):
    parts = [tmp_path / "p1.csv", tmp_path / "p2.csv"]
    for k, part in enumerate(parts, start=1):
        bd.sweep(VARY, "collide", out=part, shard=(k, 2), executor=Serial(), progress=False)
    out = tmp_path / "m.csv"
    with pytest.raises(bd.InputError, match="4 of the sweep's 8 scenarios are missing"):
        bd.merge_sweep(out, parts[:1])
    with pytest.raises(bd.InputError, match="twice"):
        bd.merge_sweep(out, [*parts, parts[0]])
    bd.sweep(VARY, "collide", out=tmp_path / "other.csv", shard=(2, 2), to=100, executor=Serial(), progress=False)
    with pytest.raises(bd.InputError, match="is not a part of the sweep"):
        bd.merge_sweep(out, [parts[0], tmp_path / "other.csv"])
    with pytest.raises(bd.InputError) as refused:
        bd.merge_sweep(tmp_path / "m.txt", parts)
    assert refused.value.field == "out"
    assert not out.exists() and not (tmp_path / "m.txt").exists()


def test_the_outputs_refusals_name_their_keyword(tmp_path):
    with pytest.raises(bd.InputError) as refused:
        bd.sweep(VARY, "collide", resume=True, progress=False)
    assert refused.value.field == "resume"
    with pytest.raises(bd.InputError) as refused:
        bd.sweep(VARY, "collide", out=tmp_path / "rows.txt", progress=False)
    assert refused.value.field == "out"
    for shard in [(3, 2), "x", (1.0, 2)]:
        with pytest.raises(bd.InputError) as refused:
            bd.sweep(VARY, "collide", shard=shard, progress=False)
        assert refused.value.field == "shard", shard
    assert not os.listdir(tmp_path)
