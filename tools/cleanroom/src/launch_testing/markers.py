"""Markers for generate_test_description and test methods."""
from __future__ import annotations

import functools
from collections.abc import Callable
from typing import TypeVar

F = TypeVar('F', bound=Callable)

_MARKERS_ATTRIBUTE = '__launch_testing_markers__'


def keep_alive(function: F) -> F:
    """Keep the launch running until the active tests are done.

    Without it a launch whose processes all exit ends (and the tests with it)
    before the active tests have finished.
    """
    markers = set(getattr(function, _MARKERS_ATTRIBUTE, ()))
    setattr(function, _MARKERS_ATTRIBUTE, markers | {'keep_alive'})
    return function


def has_marker(function: Callable, name: str) -> bool:
    """True if `function` carries the marker `name`."""
    return name in getattr(function, _MARKERS_ATTRIBUTE, ())


def retry_on_failure(*, times: int) -> Callable[[F], F]:
    """Run a test method up to `times` times until it passes."""
    if times < 1:
        raise ValueError('times must be >= 1')

    def decorator(method: F) -> F:
        @functools.wraps(method)
        def wrapper(*args, **kwargs):
            for attempt in range(times):
                try:
                    return method(*args, **kwargs)
                except AssertionError:
                    if attempt == times - 1:
                        raise
            return None
        return wrapper
    return decorator
