"""What a process wrote to its standard error."""
from .process_io import ProcessIO


class ProcessStderr(ProcessIO):
    """A chunk of a process's stderr: a ProcessIO with `fd` 2 and Jazzy's event name."""

    name = 'launch.events.process.ProcessStderr'

    def __init__(self, *, text: bytes, **kwargs: object) -> None:
        super().__init__(text=text, fd=2, **kwargs)
