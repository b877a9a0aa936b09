"""`ready_to_test_action_timeout(seconds)`: how long to wait for ReadyToTest."""
from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

F = TypeVar('F', bound=Callable)

DEFAULT_READY_TIMEOUT = 15.0
_ATTRIBUTE = '__ready_to_test_action_timeout__'


def ready_to_test_action_timeout(timeout: float) -> Callable[[F], F]:
    """Decorate generate_test_description to wait `timeout` s for ReadyToTest (default 15)."""
    def decorator(function: F) -> F:
        setattr(function, _ATTRIBUTE, float(timeout))
        return function
    return decorator


def ready_timeout_of(function: Callable) -> float:
    """The ReadyToTest timeout set on generate_test_description, or the default."""
    return getattr(function, _ATTRIBUTE, DEFAULT_READY_TIMEOUT)
