"""Ctrl-C (SIGINT, as a terminal or a notebook's interrupt sends it) stops a long call within a
second with KeyboardInterrupt, and leaves nothing half-written. Each run is a fresh Python
process that interrupts itself, so the test's own process keeps its signal handlers.

Each runs twice: started with SIGINT at its default, and started with SIGINT ignored (as nohup,
a background job of a shell or a CI runner starts it). Python installs its KeyboardInterrupt
handler only where SIGINT is at its default, so the script installs it itself, as a program
that wants Ctrl-C must."""

import json
import os
import signal
import subprocess
import sys
import textwrap

import pytest

SCRIPT = textwrap.dedent("""
    import json, os, signal, sys, threading, time
    import benchdragon as bd

    # Whatever SIGINT's disposition was inherited (ignored under nohup or in a background job),
    # Ctrl-C raises KeyboardInterrupt here.
    signal.signal(signal.SIGINT, signal.default_int_handler)

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


# How the child starts: SIGINT at its default, or ignored (inherited across exec, as nohup sets it).
STARTS = {"sigint_default": signal.SIG_DFL, "sigint_ignored": signal.SIG_IGN}


@pytest.fixture(params=sorted(STARTS))
def start(request):
    return STARTS[request.param]


def run(call: str, start) -> dict:
    env = dict(os.environ)
    done = subprocess.run([sys.executable, "-c", SCRIPT.replace("CALL", call)], capture_output=True, text=True,
                          env=env, timeout=120, preexec_fn=lambda: signal.signal(signal.SIGINT, start))
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_min_pitch_on_a_fine_grid_stops_within_a_second(start):
    # grid=1e-5 over the default range is 20,000 full runs: minutes of work.
    heard = run("bd.min_pitch(grid=1e-5, progress=False)", start)
    assert "stopped_after" in heard, heard
    assert heard["stopped_after"] < 1.0


def test_a_sweep_on_threads_stops_within_a_second(start):
    heard = run("bd.sweep({'body_length': '1.5:2.5:400'}, 'min-pitch', progress=False)", start)
    assert "stopped_after" in heard, heard
    assert heard["stopped_after"] < 1.0


def test_a_film_stops_within_a_second_and_leaves_no_file(tmp_path, start):
    out = tmp_path / "long.mp4"
    heard = run(f"bd.video(out={str(out)!r}, size=(1280, 720), speedup=0.5, progress=False)", start)
    assert "stopped_after" in heard, heard
    assert heard["stopped_after"] < 1.0
    assert list(tmp_path.iterdir()) == []
