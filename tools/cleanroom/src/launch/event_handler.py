"""Event handlers: a matcher deciding which events they take, and what they do."""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from .event import Event
from .launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from .launch_context import LaunchContext


def normalize_entities(entities: object) -> list[LaunchDescriptionEntity]:
    """Turn None, one entity or an iterable of entities into a list.

    Anything else (e.g. a handler that returns True) is a TypeError that says
    what was expected, instead of failing later in the launch.
    """
    if entities is None:
        return []
    if isinstance(entities, LaunchDescriptionEntity):
        return [entities]
    if isinstance(entities, (str, bytes)) or not hasattr(entities, '__iter__'):
        raise TypeError('expected None, a launch entity or a list of launch entities, '
                        f"got '{type(entities).__name__}'")
    result = list(entities)
    for entity in result:
        if not isinstance(entity, LaunchDescriptionEntity):
            raise TypeError('expected launch entities (actions, LaunchDescription), '
                            f"got an item of type '{type(entity).__name__}'")
    return result


class BaseEventHandler:
    """Matches events; `handle()` is called for each match.

    Before handling, the event is put into the context locals as `event` so
    that substitutions like LocalSubstitution('event.returncode') can see it.
    """

    def __init__(self, *, matcher: Callable[[Event], bool], handle_once: bool = False) -> None:
        self.__matcher = matcher
        self.__handle_once = handle_once

    @property
    def handle_once(self) -> bool:
        """True when the handler unregisters itself after the first event."""
        return self.__handle_once

    @property
    def handler_description(self) -> str | None:
        """Describes what the handler does (for introspection)."""
        return None

    @property
    def matcher_description(self) -> str | None:
        """Describes which events the handler takes (for introspection)."""
        return None

    def matches(self, event: Event) -> bool:
        """Return True if this handler takes `event`."""
        return bool(self.__matcher(event))

    def describe(self) -> tuple[str, list[LaunchDescriptionEntity]]:
        """Return a description and the entities the handler may produce.

        Both descriptions are put in quotes as they are (None too), as Jazzy prints them.
        """
        return (f"{type(self).__name__}(matcher='{self.matcher_description}', "
                f"handler='{self.handler_description}', handle_once={self.handle_once})", [])

    def handle(self, event: Event,
               context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Record the event in the context locals; unregister if `handle_once`."""
        context.extend_locals({'event': event})
        if self.__handle_once:
            context.unregister_event_handler(self)
        return None


class EventHandler(BaseEventHandler):
    """A handler that answers every matching event with fixed entities."""

    def __init__(self, *, matcher: Callable[[Event], bool], entities: object = None,
                 handle_once: bool = False) -> None:
        super().__init__(matcher=matcher, handle_once=handle_once)
        self.__entities = normalize_entities(entities) if entities is not None else None

    @property
    def entities(self) -> list[LaunchDescriptionEntity] | None:
        """The entities returned for each matching event."""
        return self.__entities

    def describe(self) -> tuple[str, list[LaunchDescriptionEntity]]:
        """Return a description and the entities."""
        text, _ = super().describe()
        return (text, list(self.__entities or []))

    def handle(self, event: Event,
               context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Return the entities."""
        super().handle(event, context)
        return self.__entities
