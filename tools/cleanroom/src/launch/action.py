"""Base class of actions, the entities that do something when visited."""
from __future__ import annotations

from typing import TYPE_CHECKING

from .condition import Condition
from .events import ExecutionComplete
from .launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from .launch_context import LaunchContext


class Action(LaunchDescriptionEntity):
    """An entity with an optional condition and an `execute()` doing its work.

    `visit()` checks the condition, runs `execute()` and announces the end of
    the action with an ExecutionComplete event (at once, or when the action's
    future completes) so that OnExecutionComplete handlers can chain work.
    """

    def __init__(self, *, condition: Condition | None = None) -> None:
        self.__condition = condition

    @property
    def condition(self) -> Condition | None:
        """The condition guarding this action, if any."""
        return self.__condition

    def describe(self) -> str:
        """Return the class name; subclasses say more."""
        return f'{type(self).__name__}'

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Execute the action if its condition holds."""
        if self.__condition is not None and not self.__condition.evaluate(context):
            return None
        try:
            return self.execute(context)
        finally:
            self.__announce_completion(context)

    def __announce_completion(self, context: LaunchContext) -> None:
        event = ExecutionComplete(action=self)
        if not context.would_handle_event(event):
            return
        future = self.get_asyncio_future()
        if future is None:
            context.emit_event_sync(event)
        else:
            future.add_done_callback(lambda _: context.emit_event_sync(event))

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Do the action's work; return entities to visit next, if any."""
        return None
