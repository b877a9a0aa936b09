"""Output of a process (or input written to it)."""
from .running_process_event import RunningProcessEvent


class ProcessIO(RunningProcessEvent):
    """A chunk of bytes a process wrote; `fd` 1 is stdout, 2 stderr (0 stdin)."""

    name = 'launch.events.process.ProcessIO'

    def __init__(self, *, text: bytes, fd: int, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__text = text
        self.__fd = fd

    @property
    def text(self) -> bytes:
        """The bytes."""
        return self.__text

    @property
    def fd(self) -> int:
        """The file descriptor number."""
        return self.__fd

    @property
    def from_stdin(self) -> bool:
        """True for input."""
        return self.__fd == 0

    @property
    def from_stdout(self) -> bool:
        """True for standard output."""
        return self.__fd == 1

    @property
    def from_stderr(self) -> bool:
        """True for standard error."""
        return self.__fd == 2
