"""assertSequentialStdout: texts appear in a process's stdout in a given order."""
from __future__ import annotations

import contextlib
from collections.abc import Iterator

from ..util.proc_lookup import resolveProcesses


class SequentialTextChecker:
    """Finds texts one after another, each after the end of the previous match."""

    def __init__(self, output: str) -> None:
        self._lines: list[str] = output.splitlines()
        self._line = 0
        self._column = 0

    def assertInText(self, msg: str) -> None:
        """Fail unless `msg` comes after the previous match."""
        for index in range(self._line, len(self._lines)):
            start = self._column if index == self._line else 0
            position = self._lines[index].find(msg, start)
            if position >= 0:
                self._line, self._column = index, position + len(msg)
                return
        raise AssertionError(
            f"'{msg}' not found in sequence after previous match.  "
            f'The output near the last matched line:\n{self.get_nearby_lines()}')

    def assertInStdout(self, msg: str) -> None:
        """Same as assertInText (the text checked is the process's stdout)."""
        self.assertInText(msg)

    def get_nearby_lines(self) -> str:
        """A few lines around the last match, for the failure message."""
        first = max(0, self._line - 2)
        return '\n'.join('  ' + line for line in self._lines[first:self._line + 3])


@contextlib.contextmanager
def assertSequentialStdout(proc_output, process, cmd_args: str | None = None
                           ) -> Iterator[SequentialTextChecker]:
    """Context manager giving a checker over the stdout of one process."""
    proc = resolveProcesses(proc_output, process=process, cmd_args=cmd_args)[0]
    yield SequentialTextChecker(proc_output.text(proc, 'stdout'))
