"""Start a command as a shell in a terminal would: with a terminal as stdin.

Jazzy's `ros2 launch` runs non-interactively when its stdin is no terminal
(under pytest-xdist it is the worker's pipe): then SIGINT to the launch is sent
on to every process, and a Ctrl-C to the whole group reaches each node twice.
With a pseudo-terminal as stdin the launch is interactive, so a group SIGINT is
exactly a terminal's Ctrl-C.  labkit.Background does the same for lessons.
"""
from __future__ import annotations

import os
import pty
import subprocess
import weakref
from collections.abc import Sequence
from typing import Any


def terminal_popen(argv: Sequence[str], **options: Any) -> subprocess.Popen:
    """subprocess.Popen(argv, **options) with a pseudo-terminal as stdin; the terminal
    is closed when the Popen object goes away."""
    main_side, terminal_side = pty.openpty()
    try:
        proc = subprocess.Popen(list(argv), stdin=terminal_side, **options)
    except BaseException:
        os.close(main_side)
        raise
    finally:
        os.close(terminal_side)
    weakref.finalize(proc, os.close, main_side)
    return proc
