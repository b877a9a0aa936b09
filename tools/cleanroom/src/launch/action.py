"""Base class of actions, the entities that do something when visited."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .condition import Condition
from .conditions import IfCondition, UnlessCondition
from .events import ExecutionComplete
from .launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from .frontend import Entity, Parser
    from .launch_context import LaunchContext


class Action(LaunchDescriptionEntity):
    """An entity with an optional condition and an `execute()` doing its work.

    `visit()` checks the condition, runs `execute()` and announces the end of
    the action with an ExecutionComplete event (at once, or when the action's
    future completes) so that OnExecutionComplete handlers can chain work.
    """

    def __init__(self, *, condition: Condition | None = None) -> None:
        self.__condition = condition

    @staticmethod
    def parse(entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        """What every frontend tag gives its action: ``(Action, kwargs)`` with a
        ``condition`` from the tag's ``if`` or ``unless`` attribute (not both);
        a tag's own parse method extends the kwargs."""
        if_text = entity.get_attr('if', optional=True)
        unless_text = entity.get_attr('unless', optional=True)
        if if_text is not None and unless_text is not None:
            raise RuntimeError("if and unless conditions can't be used simultaneously")
        kwargs: dict[str, Any] = {}
        if if_text is not None:
            kwargs['condition'] = IfCondition(
                predicate_expression=parser.parse_substitution(if_text))
        if unless_text is not None:
            kwargs['condition'] = UnlessCondition(
                predicate_expression=parser.parse_substitution(unless_text))
        return Action, kwargs

    @property
    def condition(self) -> Condition | None:
        """The condition guarding this action, if any."""
        return self.__condition

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """The entities this action holds (none; a group's are its actions)."""
        return []

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
