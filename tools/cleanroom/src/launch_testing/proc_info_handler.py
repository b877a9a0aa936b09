"""proc_info: start and exit of every launched process, and waiting for them."""
from __future__ import annotations

import threading
import time

from launch.actions import ExecuteProcess

from .util.proc_lookup import NoMatchingProcessException, _proc_to_name_and_args, resolveProcesses


class ProcInfoHandler:
    """The latest ProcessStarted / ProcessExited event of each process.

    `proc_info[process]` gives it (an action or a name); an exited process's
    event has `returncode`.
    """

    def __init__(self) -> None:
        self._events: dict[int, object] = {}
        self._actions: list[ExecuteProcess] = []

    def append(self, process_event) -> None:
        """Record a ProcessStarted or ProcessExited event."""
        action = process_event.action
        if id(action) not in self._events:
            self._actions.append(action)
        self._events[id(action)] = process_event

    def __iter__(self):
        return iter([self._events[id(a)] for a in self._actions])

    def processes(self) -> list[ExecuteProcess]:
        """The processes seen, in start order."""
        return list(self._actions)

    def process_names(self) -> list[str]:
        """Names of the processes seen."""
        return [str(a.process_details['name']) for a in self._actions]

    def __getitem__(self, key):
        """The latest event of one process (action or name)."""
        return self._events[id(resolveProcesses(self, process=key)[0])]


class ActiveProcInfoHandler(ProcInfoHandler):
    """ProcInfoHandler for active tests: processes start and exit while tests wait."""

    def __init__(self) -> None:
        super().__init__()
        self._condition = threading.Condition()

    def append(self, process_event) -> None:
        with self._condition:
            super().append(process_event)
            self._condition.notify_all()

    def processes(self) -> list[ExecuteProcess]:
        with self._condition:
            return super().processes()

    def __getitem__(self, key):
        with self._condition:
            return super().__getitem__(key)

    def _wait(self, predicate, timeout: float) -> bool:
        deadline = time.monotonic() + timeout
        with self._condition:
            while True:
                try:
                    if predicate():
                        return True
                except NoMatchingProcessException:
                    pass  # not started yet
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    return False
                self._condition.wait(remaining)

    def _has_exited(self, process, cmd_args) -> bool:
        processes = resolveProcesses(self, process=process, cmd_args=cmd_args)
        return all(getattr(self._events[id(p)], 'returncode', None) is not None
                   for p in processes)

    def assertWaitForStartup(self, process=None, cmd_args: str | None = None, *,
                             timeout: float = 10) -> None:
        """Fail unless the process has started within `timeout` seconds."""
        if not self._wait(lambda: bool(resolveProcesses(self, process=process,
                                                        cmd_args=cmd_args)), timeout):
            raise AssertionError(f'Timed out waiting for process {_describe(process)} '
                                 'to start up')

    def assertWaitForShutdown(self, process=None, cmd_args: str | None = None, *,
                              timeout: float = 10) -> None:
        """Fail unless the process has exited within `timeout` seconds."""
        if not self._wait(lambda: self._has_exited(process, cmd_args), timeout):
            raise AssertionError(f'Timed out waiting for process {_describe(process)} '
                                 'to finish')


def _describe(process) -> str:
    if isinstance(process, ExecuteProcess):
        return _proc_to_name_and_args(process)
    return repr(process)
