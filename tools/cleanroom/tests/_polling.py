"""Waiting for a state in tests: poll until it holds, fail naming it if it never does.

The one polling loop of the tests, the clean room's and the book's: it lives
here because the clean room (its own distribution, with its own tests) imports
nothing of the book, while the book's tests/_polling.py re-exports it.  Needs
only pytest, so it loads wherever the clean room's conftests do.

`wait_for` fails the test when the state never comes; `poll` hands back the
last look instead, for a test whose assertion says more than "gave up" (and it
can stop early, e.g. when the process watched has ended).
"""
from __future__ import annotations

import time
from collections.abc import Callable
from typing import TypeVar

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
