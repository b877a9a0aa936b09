"""Base class of conditions that decide whether an action runs."""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .launch_context import LaunchContext


class Condition:
    """Wraps a predicate on the launch context, evaluated when the action is visited."""

    def __init__(self, *, predicate: Callable[[LaunchContext], bool] | None = None) -> None:
        self._predicate = predicate

    def describe(self) -> str:
        """Return a description of the condition."""
        return self.__repr__()

    def evaluate(self, context: LaunchContext) -> bool:
        """Return True when the guarded action should run."""
        return self._predicate(context) if self._predicate is not None else False
