"""Base of events addressed to some processes."""
from collections.abc import Callable

from ...event import Event


class ProcessTargetedEvent(Event):
    """An event with a `process_matcher(action) -> bool` choosing its processes."""

    name = 'launch.events.process.ProcessTargetedEvent'

    def __init__(self, *, process_matcher: Callable[[object], bool]) -> None:
        self.__process_matcher = process_matcher

    @property
    def process_matcher(self) -> Callable[[object], bool]:
        """Predicate on ExecuteProcess actions."""
        return self.__process_matcher
