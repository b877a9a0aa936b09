"""Run a launch in this process and record what it did; find processes the tests left.

One copy for the clean room's tests (issue 13): conftest.py's `run_launch` and
session leftover check (launch/, launch_ros/) and testing/'s per-test check.
"""
from __future__ import annotations

import itertools
import sys
from typing import Any

import psutil
import pytest
import yaml
from launch import LaunchDescription, LaunchService, launch_context
from launch.actions import RegisterEventHandler, Shutdown, TimerAction
from launch.event_handlers import OnProcessStart


# Every process the tests start carries this variable (children inherit it), so
# the session can find the ones that survived, whoever started them.
def read_param_files(cmd: list[str]) -> list:
    """Replace each `--params-file PATH` by {'path': PATH, 'content': parsed YAML}.

    Read while the process starts, since launch_ros's temporary files go away
    with the launch.
    """
    out: list = []
    i = 0
    while i < len(cmd):
        if cmd[i] == '--params-file' and i + 1 < len(cmd):
            path = cmd[i + 1]
            try:
                with open(path) as handle:
                    content = yaml.safe_load(handle)
            except OSError as exc:
                content = f'unreadable: {exc.strerror}'
            out += ['--params-file', {'path': path, 'content': content}]
            i += 2
        else:
            out.append(cmd[i])
            i += 1
    return out


class LaunchResult:
    """Exit code, started processes and screen output of one in-process launch.

    Each process is a dict: name, pid, cmd (param files read into dicts), env, cwd.
    """

    def __init__(self, returncode: int, processes: list[dict[str, Any]], output: str) -> None:
        self.returncode = returncode
        self.processes = processes
        self.output = output

    @property
    def names(self) -> list[str]:
        """Process names, in the order they started (ProcessStarted events)."""
        return [p['name'] for p in self.processes]

    def process(self, name: str) -> dict[str, Any]:
        """The (first) started process called `name`."""
        return next(p for p in self.processes if p['name'] == name)

    def by_name(self, prefix: str) -> dict[str, Any]:
        """The one process whose `name-N` starts with `prefix-`."""
        matches = [p for p in self.processes if p['name'].rsplit('-', 1)[0] == prefix]
        assert len(matches) == 1, (prefix, [p['name'] for p in self.processes])
        return matches[0]

    def node_cmd(self, node_name: str) -> list:
        """The command line of the one process started with `-r __node:=node_name`."""
        matches = [p['cmd'] for p in self.processes if '__node:=' + node_name in p['cmd']]
        assert len(matches) == 1, (node_name, [p['cmd'] for p in self.processes])
        return matches[0]

    def user_lines(self) -> list[str]:
        """The messages LogInfo printed."""
        prefix = '[INFO] [launch.user]: '
        return [line[len(prefix):] for line in self.output.splitlines()
                if line.startswith(prefix)]

    def error_text(self) -> str:
        """The [ERROR] [launch] message, continuation lines included."""
        lines = self.output.splitlines()
        prefix = '[ERROR] [launch]: '
        start = next(i for i, line in enumerate(lines) if line.startswith(prefix))
        rest = [line for line in lines[start + 1:] if line.startswith(' - ')]
        return '\n'.join([lines[start][len(prefix):], *rest])


def run_in_process(capture: pytest.CaptureFixture, entities: list, *, argv: tuple = (),
                   shutdown_after: float | None = None, debug: bool = False) -> LaunchResult:
    """Run entities in a LaunchService in this process and return a LaunchResult.

    The launch ends when idle, or `shutdown_after` seconds after it started.
    `output` is what this launch wrote to stdout, read from `capture` (capfd,
    so C code in this process counts too), which keeps it.  Processes the
    launch started must be gone when this returns.
    """
    processes: list[dict[str, Any]] = []

    def on_start(event: Any, context: Any) -> None:
        processes.append({'name': event.process_name, 'pid': event.pid,
                          'cmd': read_param_files([str(t) for t in event.cmd]),
                          'env': dict(event.env or {}), 'cwd': event.cwd})

    extra = [] if shutdown_after is None else [
        TimerAction(period=shutdown_after, actions=[Shutdown(reason='test done')])]
    earlier = capture.readouterr()
    # Number processes from 1, as `ros2 launch` (a Python process of its own) does:
    # the count goes on across the launches of one Python process (launch_context).
    launch_context._PROCESS_NUMBERS = itertools.count(1)
    service = LaunchService(argv=list(argv), debug=debug)
    service.include_launch_description(LaunchDescription(
        [RegisterEventHandler(OnProcessStart(on_start=on_start)), *entities, *extra]))
    returncode = service.run()
    captured = capture.readouterr()
    # Put all back: a failing test's report shows it, and a test may read capfd itself.
    sys.stdout.write(earlier.out + captured.out)
    sys.stderr.write(earlier.err + captured.err)
    alive = [p for p in processes if psutil.pid_exists(p['pid'])
             and psutil.Process(p['pid']).status() != psutil.STATUS_ZOMBIE]
    assert not alive, f'processes outlived the launch: {alive}'
    return LaunchResult(returncode, processes, captured.out)
