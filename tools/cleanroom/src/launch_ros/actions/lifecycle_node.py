"""LifecycleNode: a Node whose lifecycle transitions the launch file drives.

Transitions are requested with `EmitEvent(event=ChangeState(...))` and
reported as StateTransition events (see OnStateTransition), through the
node's `<node>/change_state` service and `<node>/transition_event` topic.
"""
from __future__ import annotations

from typing import Any

from launch import LaunchContext

from ..utilities.lifecycle_manager import LifecycleManager
from .node import Node


class LifecycleNode(Node):
    """Start a managed node; `name` and `namespace` are required to find its services."""

    def __init__(self, *, name: Any, namespace: Any, **kwargs: Any) -> None:
        super().__init__(name=name, namespace=namespace, **kwargs)
        self.__manager: LifecycleManager | None = None

    @property
    def is_lifecycle_node(self) -> bool:
        return True

    def get_lifecycle_event_manager(self) -> LifecycleManager | None:
        return self.__manager

    def execute(self, context: LaunchContext) -> list[Any] | None:
        entities = super().execute(context)
        self.__manager = LifecycleManager(self, context)
        self.__manager.start()
        return entities
