"""Ctrl-C (SIGINT, as a terminal or a notebook's interrupt sends it) stops a long call within a
second with KeyboardInterrupt, and leaves nothing half-written. Each run is a fresh Python
process that interrupts itself, so the test's own process keeps its signal handlers."""

import json
import os
import subprocess
import sys
import textwrap

import pytest

SCRIPT = textwrap.dedent("""
    import json, os, signal, sys, threading, time
    import benchdragon as bd

    sent = {}
    def interrupt():
        time.sleep(0.5)
        sent["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt, daemon=True).start()
    started = time.monotonic()
    try:
        CALL
        print(json.dumps({"finished": time.monotonic() - started}))
    except KeyboardInterrupt:
        print(json.dumps({"stopped_after": time.monotonic() - sent["at"]}))
""")


def run(call: str) -> dict:
    env = dict(os.environ)
    done = subprocess.run([sys.executable, "-c", SCRIPT.replace("CALL", call)], capture_output=True, text=True,
                          env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_min_pitch_on_a_fine_grid_stops_within_a_second():
    # grid=1e-5 over the default range is 20,000 full runs: minutes of work.
    heard = run("bd.min_pitch(grid=1e-5, progress=False)")
    assert "stopped_after" in heard, heard
    assert heard["stopped_after"] < 1.0


def test_a_sweep_on_threads_stops_within_a_second():
    heard = run("bd.sweep({'body_length': '1.5:2.5:400'}, 'min-pitch', progress=False)")
    assert "stopped_after" in heard, heard
    assert heard["stopped_after"] < 1.0


def test_a_film_stops_within_a_second_and_leaves_no_file(tmp_path):
    out = tmp_path / "long.mp4"
    heard = run(f"bd.video(out={str(out)!r}, size=(1280, 720), speedup=0.5, progress=False)")
    assert "stopped_after" in heard, heard
    assert heard["stopped_after"] < 1.0
    assert list(tmp_path.iterdir()) == []
