"""Where a process's output goes: lines to screen/log files, and an optional cache."""
from __future__ import annotations

from collections.abc import Callable

from ..logging import get_output_loggers


class ProcessOutput:
    """Splits raw output chunks into lines for the output loggers.

    Lines are written as soon as they are complete; a last line without a
    newline is written when the process exits (flush()).  With `cached`,
    everything is also kept for ExecuteProcess.get_stdout()/get_stderr().
    `screen_line` turns a line into what the screen shows (ExecuteProcess's
    `output_format`); without it the screen shows `[<process name>] <line>`.
    """

    def __init__(self, process_name: str, output: str, cached: bool, *,
                 screen_line: Callable[[str], str] | None = None) -> None:
        self.__writers = get_output_loggers(process_name, output, screen_line=screen_line)
        self.__buffers: dict[int, bytes] = {}
        self.__cached = cached
        self.__cache: dict[int, list[str]] = {1: [], 2: []}

    def write(self, fd: int, data: bytes) -> None:
        """Take a chunk from stdout (fd 1) or stderr (fd 2)."""
        if self.__cached:
            self.__cache[fd].append(data.decode(errors='replace'))
        *lines, rest = (self.__buffers.get(fd, b'') + data).split(b'\n')
        self.__buffers[fd] = rest
        writer = self.__writers[0 if fd == 1 else 1]
        for line in lines:
            writer.line(line.decode(errors='replace').rstrip('\r'))

    def flush(self) -> None:
        """Write what is left of unfinished lines."""
        for fd, rest in self.__buffers.items():
            if rest:
                self.__writers[0 if fd == 1 else 1].line(
                    rest.decode(errors='replace').rstrip('\r'))
        self.__buffers.clear()

    def cached(self, fd: int) -> str:
        """Everything the process wrote to `fd` so far (cached mode only)."""
        return ''.join(self.__cache[fd])
