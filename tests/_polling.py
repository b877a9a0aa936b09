"""Waiting for a state in tests: poll until it holds, fail naming it if it never does.

The one polling loop of the tests: `wait_for` fails the test when the state never
comes; `poll` hands back the last look instead, for a test whose assertion says
more than "gave up" (and it can stop early, e.g. when the process watched has ended).
"""
from __future__ import annotations

import time
from collections.abc import Callable
from typing import TypeVar

import psutil
import pytest

T = TypeVar('T')
INTERVAL = 0.1


def _sleep() -> None:
    time.sleep(INTERVAL)


def poll(predicate: Callable[[], T], timeout: float,
         stop: Callable[[], bool] = lambda: False, pause: Callable[[], None] = _sleep) -> T:
    """Call ``predicate`` until it gives a true value, ``stop()`` holds or ``timeout``
    seconds have passed; return its last value (a state, not a duration).  Between
    looks it calls ``pause`` (a short sleep; or spinning an executor, for a test
    whose state arrives in callbacks)."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value or stop() or time.monotonic() >= deadline:
            return value
        pause()


def wait_for(predicate: Callable[[], T], timeout: float, what: str,
             pause: Callable[[], None] = _sleep) -> T:
    """Poll ``predicate`` until it gives a true value; fail naming ``what`` if it never does."""
    value = poll(predicate, timeout, pause=pause)
    if not value:
        pytest.fail(f'gave up after {timeout} s waiting for {what}')
    return value


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
