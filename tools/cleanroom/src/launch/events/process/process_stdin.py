"""Input for a process: a ProcessIO event on its stdin (fd 0)."""
from .process_io import ProcessIO


class ProcessStdin(ProcessIO):
    """`text` for the standard input of the process `action` names.

    As on Jazzy, the fields are those of every running-process event (action,
    name, cmd, cwd, env, pid), and the process's own handler does not write
    the text: it logs a warning that names the handler.
    """

    name = 'launch.events.process.ProcessStdin'

    def __init__(self, *, text: bytes, **kwargs: object) -> None:
        super().__init__(text=text, fd=0, **kwargs)
