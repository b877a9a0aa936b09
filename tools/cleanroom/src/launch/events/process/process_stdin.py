"""Write to the standard input of some processes."""
from collections.abc import Callable

from .process_targeted_event import ProcessTargetedEvent


class ProcessStdin(ProcessTargetedEvent):
    """Write `text` (bytes or str) to the stdin of the matching processes."""

    name = 'launch.events.process.ProcessStdin'

    def __init__(self, *, text: object, process_matcher: Callable[[object], bool]) -> None:
        super().__init__(process_matcher=process_matcher)
        self.__text = text.encode() if isinstance(text, str) else text

    @property
    def text(self) -> bytes:
        """The bytes to write."""
        return self.__text
