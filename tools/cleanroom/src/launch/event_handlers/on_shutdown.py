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


class OnShutdown(BaseEventHandler):
    """Run `on_shutdown` (entities, or a callable `(event, context)`) when the launch ends.

    The LaunchService emits Shutdown whenever it finishes (idle, requested,
    Ctrl-C or after an error), so this is the place for cleanup.
    """

    def __init__(self, *, on_shutdown: object, **kwargs: object) -> None:
        super().__init__(matcher=lambda event: isinstance(event, Shutdown), **kwargs)
        if callable(on_shutdown) and not isinstance(on_shutdown, LaunchDescriptionEntity):
            self.__callback: Callable | None = on_shutdown
            self.__entities: list[LaunchDescriptionEntity] = []
        else:
            self.__callback = None
            self.__entities = normalize_entities(on_shutdown)

    @property
    def handler_description(self) -> str:
        """What the handler does."""
        return '<function>' if self.__callback is not None else '<actions>'

    @property
    def matcher_description(self) -> str:
        """Which events the handler takes."""
        return 'event issubclass of launch.events.Shutdown'

    def describe(self) -> tuple[str, list[LaunchDescriptionEntity]]:
        """Return a description and the entities."""
        text, _ = super().describe()
        return (text, list(self.__entities))

    def handle(self, event: Event,
               context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Return the entities, or what the callable returns."""
        super().handle(event, context)
        if self.__callback is not None:
            return normalize_entities(self.__callback(event, context))
        return self.__entities
