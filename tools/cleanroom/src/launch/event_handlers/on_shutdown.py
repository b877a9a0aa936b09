"""Handle the Shutdown event."""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ..event import Event
from ..event_handler import BaseEventHandler, normalize_entities
from ..events import Shutdown
from ..launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


def gen_handler(entities: list[LaunchDescriptionEntity]) -> Callable:
    """Wrap fixed entities in a callable: Jazzy does, and `ros2 launch -p` names it so."""
    def handler(event: Event, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        return entities
    return handler


class OnShutdown(BaseEventHandler):
    """Run `on_shutdown` (entities, or a callable `(event, context)`) when the launch ends.

    The LaunchService emits Shutdown whenever it finishes (idle, requested,
    Ctrl-C or after an error), so this is the place for cleanup.
    """

    def __init__(self, *, on_shutdown: object, **kwargs: object) -> None:
        super().__init__(matcher=lambda event: isinstance(event, Shutdown), **kwargs)
        if callable(on_shutdown) and not isinstance(on_shutdown, LaunchDescriptionEntity):
            self.__callback: Callable = on_shutdown
        else:
            self.__callback = gen_handler(normalize_entities(on_shutdown))

    @property
    def handler_description(self) -> str:
        """What the handler does: the callable, as str() shows it."""
        return str(self.__callback)

    @property
    def matcher_description(self) -> str:
        """Which events the handler takes."""
        return 'event issubclass of launch.events.Shutdown'

    def handle(self, event: Event,
               context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Return what the callable returns (the entities, when entities were given)."""
        super().handle(event, context)
        return normalize_entities(self.__callback(event, context))
