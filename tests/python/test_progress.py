"""Progress is shown as the tool shows its progress line: on a terminal (or in Jupyter), redrawn
at most ten times a second; on a stderr redirected to a file or a pipe, nothing at all. Each
call runs in a fresh Python process whose stderr is the file or the terminal."""

import json
import os
import subprocess
import sys
import textwrap
import threading
import time

import pytest

CALL = textwrap.dedent("""
    import json, time
    import benchdragon as bd
    started = time.monotonic()
    bd.turnaround()
    print(json.dumps({"seconds": time.monotonic() - started}))
""")


def test_nothing_on_a_redirected_stderr(tmp_path):
    log = tmp_path / "stderr.txt"
    with open(log, "w") as err:
        done = subprocess.run([sys.executable, "-c", CALL], stdout=subprocess.PIPE, stderr=err, text=True,
                              timeout=300)
    assert done.returncode == 0, log.read_text()
    assert log.read_text() == ""


def test_on_a_terminal_at_most_ten_redraws_a_second():
    pytest.importorskip("tqdm", reason="progress bars need tqdm (Debian: python3-tqdm)")
    pty = pytest.importorskip("pty")
    try:
        master, slave = pty.openpty()
    except OSError as e:  # a container without /dev/pts
        pytest.skip(f"no terminal to draw on: {e}")
    child = subprocess.Popen([sys.executable, "-c", CALL], stdout=subprocess.PIPE, stderr=slave, text=True)
    os.close(slave)
    shown = bytearray()

    def read():
        while True:
            try:
                chunk = os.read(master, 65536)
            except OSError:  # EIO: the child's end closed
                return
            if not chunk:
                return
            shown.extend(chunk)

    reader = threading.Thread(target=read)
    reader.start()
    out, _ = child.communicate(timeout=300)
    reader.join(timeout=10)
    os.close(master)
    assert child.returncode == 0, shown.decode(errors="replace")
    seconds = json.loads(out.strip().splitlines()[-1])["seconds"]
    text = shown.decode(errors="replace")
    redraws = text.count("\r")
    if seconds > 0.7:  # the bar waits half a second before it draws: a faster call shows none
        assert "samples" in text, text
    # A redraw each tenth of a second after the first half second, and the line erased at the end.
    assert redraws <= 10 * seconds + 3, (redraws, seconds)
