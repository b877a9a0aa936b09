"""The handler that visits launch descriptions given to LaunchService."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..event import Event
from ..event_handler import BaseEventHandler
from ..events import IncludeLaunchDescription
from ..launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class OnIncludeLaunchDescription(BaseEventHandler):
    """Return the launch description carried by an IncludeLaunchDescription event."""

    def __init__(self, **kwargs: object) -> None:
        super().__init__(matcher=lambda e: isinstance(e, IncludeLaunchDescription), **kwargs)

    def handle(self, event: Event,
               context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Return [the launch description]."""
        super().handle(event, context)
        return [event.launch_description]
