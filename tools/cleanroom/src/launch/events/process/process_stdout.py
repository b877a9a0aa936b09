"""What a process wrote to its standard output."""
from .process_io import ProcessIO


class ProcessStdout(ProcessIO):
    """A chunk of a process's stdout: a ProcessIO with `fd` 1 and Jazzy's event name."""

    name = 'launch.events.process.ProcessStdout'

    def __init__(self, *, text: bytes, **kwargs: object) -> None:
        super().__init__(text=text, fd=1, **kwargs)
