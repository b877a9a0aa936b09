"""Stopping the processes the `ros2` tests start, in one place: conftest.py and the
test modules import it from here (a test module cannot import `conftest`: with
several conftest.py files in the tree, that name is whichever came first)."""
from __future__ import annotations

import os
import signal
import subprocess


def stop_process(proc: subprocess.Popen, grace: float = 5.0) -> None:
    """SIGINT the process group, then SIGKILL whatever is left; always reap."""
    for sig, wait in ((signal.SIGINT, grace), (signal.SIGKILL, grace)):
        if proc.poll() is not None:
            break
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            break
        try:
            proc.wait(timeout=wait)
        except subprocess.TimeoutExpired:
            continue
    proc.wait()
