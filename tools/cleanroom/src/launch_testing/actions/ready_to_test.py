"""ReadyToTest: the point in a launch description where active tests may start."""
from __future__ import annotations

from collections.abc import Callable

from launch import Action, LaunchContext, LaunchDescriptionEntity

_CONTEXT_CALLBACKS = '_launch_testing_ready_callbacks'


def add_ready_callback(context: LaunchContext, callback: Callable[[], None]) -> None:
    """Call `callback` whenever a ReadyToTest runs in this launch (for test runners)."""
    callbacks = getattr(context, _CONTEXT_CALLBACKS, None)
    if callbacks is None:
        callbacks = []
        setattr(context, _CONTEXT_CALLBACKS, callbacks)
    callbacks.append(callback)


class ReadyToTest(Action):
    """When executed, tells the test runner that the system under test is up."""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.__callbacks: list[Callable[[], None]] = []

    def _add_callback(self, callback: Callable[[], None]) -> None:
        """Register what to call once this action runs (used by the test runners)."""
        self.__callbacks.append(callback)

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Signal readiness to every registered runner."""
        for callback in [*self.__callbacks, *getattr(context, _CONTEXT_CALLBACKS, [])]:
            callback()
        return None
