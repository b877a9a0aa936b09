"""Register or unregister an event handler, and emit events."""
from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..action import Action
from ..event import Event
from ..event_handler import BaseEventHandler
from ..events import Shutdown as ShutdownEvent
from ..events.process import ProcessExited
from ..launch_description_entity import LaunchDescriptionEntity
from ..logging import get_logger

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class RegisterEventHandler(Action):
    """Add `event_handler` to the launch when visited."""

    def __init__(self, event_handler: BaseEventHandler, **kwargs: object) -> None:
        super().__init__(**kwargs)
        if not isinstance(event_handler, BaseEventHandler):
            raise TypeError(f"RegisterEventHandler expected an event handler, "
                            f"got '{type(event_handler)}'")
        self.__event_handler = event_handler

    @property
    def event_handler(self) -> BaseEventHandler:
        """The handler."""
        return self.__event_handler

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Sequence[LaunchDescriptionEntity]]]:
        """The entities the handler may produce."""
        text, entities = self.__event_handler.describe()
        return [(text, entities)] if entities else []

    def execute(self, context: LaunchContext) -> None:
        """Register the handler."""
        context.register_event_handler(self.__event_handler)


class UnregisterEventHandler(Action):
    """Remove `event_handler` from the launch when visited."""

    def __init__(self, event_handler: BaseEventHandler, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__event_handler = event_handler

    @property
    def event_handler(self) -> BaseEventHandler:
        """The handler."""
        return self.__event_handler

    def execute(self, context: LaunchContext) -> None:
        """Unregister the handler (RuntimeError if it was not registered)."""
        try:
            context.unregister_event_handler(self.__event_handler)
        except ValueError:
            raise RuntimeError(f"Cannot unregister event handler '{self.__event_handler}' "
                               'which is not registered') from None


class EmitEvent(Action):
    """Emit `event` when visited."""

    def __init__(self, *, event: Event, **kwargs: object) -> None:
        super().__init__(**kwargs)
        if not isinstance(event, Event):
            raise TypeError(f"EmitEvent expected a launch Event, got '{type(event)}'")
        self.__event = event

    @property
    def event(self) -> Event:
        """The event."""
        return self.__event

    def describe(self) -> str:
        """Return a description."""
        return f'EmitEvent(event={type(self.__event).__name__})'

    def execute(self, context: LaunchContext) -> None:
        """Queue the event."""
        context.emit_event_sync(self.__event)


class Shutdown(EmitEvent):
    """Shut the launch down, giving `reason`."""

    def __init__(self, *, reason: str = 'reason not given', **kwargs: object) -> None:
        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)

    def execute(self, context: LaunchContext) -> None:
        """Say which process was required when a process exit runs it, as Jazzy logs."""
        event = context.get_locals_as_dict().get('event')
        if isinstance(event, ProcessExited):  # e.g. ExecuteProcess(on_exit=Shutdown())
            get_logger('launch').info(
                f'process[{event.process_name}] was required: shutting down launched system')
        super().execute(context)


# Shown in reprs (`ros2 launch -p` prints them) under the module names Jazzy uses.
RegisterEventHandler.__module__ = 'launch.actions.register_event_handler'
UnregisterEventHandler.__module__ = 'launch.actions.unregister_event_handler'
EmitEvent.__module__ = 'launch.actions.emit_event'
Shutdown.__module__ = 'launch.actions.shutdown_action'
