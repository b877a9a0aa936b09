"""proc_output: the output of every launched process, and waiting for more of it."""
from __future__ import annotations

import re
import threading
import time
from collections.abc import Callable

from launch.actions import ExecuteProcess

from .util.proc_lookup import NoMatchingProcessException, resolveProcesses

Expected = str | re.Pattern[str] | Callable[[str], bool]


def _text(event) -> str:
    data = event.text
    return data.decode(errors='replace') if isinstance(data, bytes) else str(data)


def _found(expected: Expected, text: str) -> bool:
    if isinstance(expected, re.Pattern):
        return expected.search(text) is not None
    if callable(expected):
        return bool(expected(text))
    return str(expected) in text


class IoHandler:
    """Holds the ProcessIO events of all processes, in arrival order.

    `proc_output[process]` gives the events of one process (an action or a name).
    """

    def __init__(self) -> None:
        self._events: list[object] = []
        self._by_action: dict[int, list[object]] = {}
        self._actions: list[ExecuteProcess] = []

    def append(self, process_io) -> None:
        """Record one ProcessIO event."""
        action = process_io.action
        if id(action) not in self._by_action:
            self._by_action[id(action)] = []
            self._actions.append(action)
        self._by_action[id(action)].append(process_io)
        self._events.append(process_io)

    def __iter__(self):
        return iter(list(self._events))

    def processes(self) -> list[ExecuteProcess]:
        """The processes that produced output, in order of their first output."""
        return list(self._actions)

    def process_names(self) -> list[str]:
        """Names of the processes that produced output."""
        return [str(p.process_details['name']) for p in self._actions]

    def __getitem__(self, key) -> list[object]:
        """The ProcessIO events of one process (action or name)."""
        processes = resolveProcesses(self, process=key)
        return list(self._by_action[id(processes[0])])

    def text(self, process: ExecuteProcess, stream: str | None = None) -> str:
        """Everything `process` wrote to `stream` ('stdout', 'stderr' or both when None)."""
        events = self._by_action.get(id(process), [])
        wanted = {'stdout': (1,), 'stderr': (2,), None: (1, 2)}.get(stream)
        if wanted is None:
            raise ValueError(f"stream must be 'stdout', 'stderr' or None, not {stream!r}")
        return ''.join(_text(e) for e in events if e.fd in wanted)


class ActiveIoHandler(IoHandler):
    """IoHandler for active tests: output keeps arriving while tests wait for it."""

    def __init__(self) -> None:
        super().__init__()
        self._condition = threading.Condition()

    def append(self, process_io) -> None:
        """Record one ProcessIO event and wake whoever waits for output."""
        with self._condition:
            super().append(process_io)
            self._condition.notify_all()

    def processes(self) -> list[ExecuteProcess]:
        with self._condition:
            return super().processes()

    def track(self, process_name: str) -> None:
        """Kept for API compatibility: every process is tracked."""

    def _matches(self, expected_output: Expected, process, cmd_args, output_filter,
                 stream, strict_proc_matching) -> bool:
        processes = resolveProcesses(self, process=process, cmd_args=cmd_args,
                                     strict_proc_matching=strict_proc_matching)
        for proc in processes:
            text = self.text(proc, stream)
            if output_filter is not None:
                text = output_filter(text)
            if _found(expected_output, text):
                return True
        return False

    def waitFor(self, expected_output: Expected, process=None, cmd_args: str | None = None,
                *, strict_proc_matching: bool = True, output_filter=None, timeout: float = 10,
                stream: str | None = None) -> bool:
        """Wait until `expected_output` appears; False after `timeout` seconds.

        Raises NoMatchingProcessException if, at the end, the process produced
        no output at all.
        """
        deadline = time.monotonic() + timeout
        with self._condition:
            while True:
                try:
                    if self._matches(expected_output, process, cmd_args, output_filter,
                                     stream, strict_proc_matching):
                        return True
                except NoMatchingProcessException:
                    pass  # no output from that process yet
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    break
                self._condition.wait(remaining)
            # a last look, letting "no such process" surface to the test
            return self._matches(expected_output, process, cmd_args, output_filter,
                                 stream, strict_proc_matching)

    def assertWaitFor(self, *args, **kwargs) -> None:
        """waitFor(), failing the test when the output did not come in time."""
        if not self.waitFor(*args, **kwargs):
            raise AssertionError('Waiting for output timed out')
