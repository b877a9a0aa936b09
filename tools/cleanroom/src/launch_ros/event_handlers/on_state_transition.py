"""OnStateTransition: run entities when a lifecycle node reaches a state."""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launch import EventHandler

from ..events.lifecycle import StateTransition


class OnStateTransition(EventHandler):
    """Handle StateTransition events, optionally filtered by node and labels.

    `target_lifecycle_node` is the LifecycleNode action; `transition`,
    `start_state` and `goal_state` are labels such as 'activate', 'inactive'.
    A custom `matcher` replaces all of those filters.
    """

    def __init__(self, *, entities: Any, target_lifecycle_node: Any = None,
                 transition: str | None = None, start_state: str | None = None,
                 goal_state: str | None = None,
                 matcher: Callable[[Any], bool] | None = None, **kwargs: Any) -> None:
        self.__target = target_lifecycle_node
        self.__filters = {'transition': transition, 'start_state': start_state,
                          'goal_state': goal_state}
        super().__init__(matcher=matcher or self._matches, entities=entities, **kwargs)

    def _matches(self, event: Any) -> bool:
        if not isinstance(event, StateTransition):
            return False
        if self.__target is not None and event.action is not self.__target:
            return False
        return all(expected is None or getattr(event, attr) == expected
                   for attr, expected in self.__filters.items())

    @property
    def handler_description(self) -> str:
        return '<actions>'

    @property
    def matcher_description(self) -> str:
        """Which events: Jazzy names the target node by its id only (the labels not at all)."""
        if self.__target is None:
            return 'event == StateTransition'
        node = f'LifecycleNode({hex(id(self.__target))})'
        return f'event == StateTransition and event.action == {node}'
