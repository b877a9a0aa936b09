"""Emitted when a process has exited."""
from .running_process_event import RunningProcessEvent


class ProcessExited(RunningProcessEvent):
    """A process exited; `returncode` is negative when a signal ended it."""

    name = 'launch.events.process.ProcessExited'

    def __init__(self, *, returncode: int, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__returncode = returncode

    @property
    def returncode(self) -> int:
        """The exit code."""
        return self.__returncode
