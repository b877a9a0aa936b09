"""Waiting for a state in tests: poll until it holds, fail naming it if it never does.

`poll` and `wait_for` are the one polling loop of all the tests, kept with the
clean room's tests (tools/cleanroom/tests/_polling.py), which import nothing of the
book; they are importable here as `cleanroom.tests._polling` because the root's
editable install puts tools/ on sys.path.  `wait_for` fails the test when the
state never comes; `poll` hands back the last look instead, for a test whose
assertion says more than "gave up" (and it can stop early, e.g. when the process
watched has ended).  `still_running` is the book's own.
"""
from __future__ import annotations

import psutil
from cleanroom.tests._polling import poll, wait_for

__all__ = ['poll', 'still_running', 'wait_for']


def still_running(pids: list[int]) -> list[int]:
    """The pids among ``pids`` that still run (zombies count as gone)."""
    alive = []
    for pid in pids:
        try:
            if psutil.Process(pid).status() != psutil.STATUS_ZOMBIE:
                alive.append(pid)
        except psutil.NoSuchProcess:
            continue
    return alive
