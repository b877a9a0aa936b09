"""Processes that cannot outlive their starter, and process groups stopped for good.

``die_with_parent`` is used between fork and exec (``Popen(preexec_fn=...)``)
by the clean room's launch (SIGKILL: a launch that is killed or crashes takes
its processes along) and its ``ros2 run`` (SIGTERM); Linux only, elsewhere it
does nothing.  ``stop_group`` signals a whole process group, escalating until
it is empty: labkit's background processes and watchdog, and the clean room's
launch_testing pytest plugin stop what they started with it.
"""
from __future__ import annotations

import ctypes
import os
import time

import psutil

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


def group_members(pgid: int) -> list[psutil.Process]:
    """Live (non-zombie) processes of a process group."""
    members = []
    for proc in psutil.process_iter(['status']):
        try:
            if os.getpgid(proc.pid) == pgid and proc.info['status'] != psutil.STATUS_ZOMBIE:
                members.append(proc)
        except (ProcessLookupError, psutil.Error):
            continue
    return members


def stop_group(pgid: int, escalation: tuple[tuple[int, float], ...]) -> bool:
    """Send each (signal, seconds) of ``escalation`` in turn to the group, waiting up to
    those seconds for it to empty; True once it is empty."""
    for sig, wait in escalation:
        if not group_members(pgid):
            return True
        try:
            os.killpg(pgid, sig)
        except ProcessLookupError:
            return True
        deadline = time.monotonic() + wait
        while time.monotonic() < deadline:
            if not group_members(pgid):
                return True
            time.sleep(0.05)
    return not group_members(pgid)
