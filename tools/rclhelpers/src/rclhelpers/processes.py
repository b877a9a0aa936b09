"""A child process that cannot outlive the process that started it.

Used between fork and exec (``subprocess.Popen(preexec_fn=...)``) by the
clean room's launch (SIGKILL: a launch that is killed or crashes takes its
processes along) and its ``ros2 run`` (SIGTERM).  Linux only; elsewhere it
does nothing.
"""
from __future__ import annotations

import ctypes
import os

_PR_SET_PDEATHSIG = 1

try:
    _libc: ctypes.CDLL | None = ctypes.CDLL(None, use_errno=True)
except OSError:  # pragma: no cover - not Linux/glibc
    _libc = None


def die_with_parent(parent_pid: int, signum: int) -> None:
    """preexec_fn: the kernel sends ``signum`` to the child when its parent thread ends.

    Followed by a check that the parent is still ``parent_pid``: a parent that
    died between fork and prctl would otherwise leave the child behind.
    """
    if _libc is not None:
        _libc.prctl(_PR_SET_PDEATHSIG, signum, 0, 0, 0)
    if os.getppid() != parent_pid:
        os._exit(1)
