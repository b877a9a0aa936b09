"""Run the student's launch file as their terminal would, and record what it did.

A check must not wait forever for a node a wrong answer never starts, nor
judge before a right answer is up.  The launch log says when it is up: each
process is announced (`process started with pid [N]`), and each node of
this book logs a line as it starts (`[process-N] [INFO] [t] [node]: ...`).
The probe waits until every announced process has logged or ended and the
nodes they named are in the graph (at once if that includes every expected
node, else once no new process was announced for a moment), or until the
launch exits, or `timeout` runs out.  A launch that should refuse to start
needs no such wait: `until_first_process` stops it at its first process.
"""
from __future__ import annotations

import re
import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from labkit import observer
from labkit.commands import launch
from labkit.grading.student_package import StudentPackage
from labkit.graph import GraphSnapshot, graph

STARTED = re.compile(r'^\[INFO\] \[(?P<process>[^\]]+)\]: process started with pid \[\d+\]')
ENDED = re.compile(r'^\[(?:INFO|ERROR)\] \[(?P<process>[^\]]+)\]: '
                   r'process (?:has died|has finished)')
NODE_LINE = re.compile(r'^\[(?P<process>[^\]\s]+)\] \[(?:DEBUG|INFO|WARN|ERROR|FATAL)\] '
                       r'\[[\d.]+\] \[(?P<logger>[^\]]+)\]: ')
LAUNCH_ERROR = re.compile(r'^\[ERROR\] \[launch[^\]]*\]: ')
#: How long the set of announced processes must stay unchanged before the
#: probe trusts that the launch has started all of them.  Longer while an
#: expected node is missing: on a loaded machine a launch that includes
#: other launch files can pause for seconds between its first process and
#: the next (7.4's night shift was once judged with only turtlesim up).
PROCESSES_SETTLED = 1.0
PROCESSES_SETTLED_WITH_NODES_MISSING = 6.0


@dataclass
class LaunchProbe:
    """What one `ros2 launch` did before it was stopped."""

    command: str
    lines: list[str]
    returncode: int | None
    exited_by_itself: bool
    snapshot: GraphSnapshot | None
    processes: list[str] = field(default_factory=list)
    #: node full name -> the process labels whose log lines carry that node name
    node_processes: dict[str, list[str]] = field(default_factory=dict)
    #: what `inspect` returned while the launch ran (e.g. parameters read)
    inspected: Any = None

    @property
    def nodes(self) -> tuple[str, ...]:
        return self.snapshot.nodes if self.snapshot else ()

    def launch_errors(self) -> list[str]:
        """Error lines of launch itself (e.g. an executable that was not found)."""
        return [line for line in self.lines if LAUNCH_ERROR.match(line)]

    def publishers(self, topic: str) -> tuple[str, ...]:
        if self.snapshot is None or topic not in self.snapshot.topics:
            return ()
        return self.snapshot.publishers(topic)

    def subscribers(self, topic: str) -> tuple[str, ...]:
        if self.snapshot is None or topic not in self.snapshot.topics:
            return ()
        return self.snapshot.subscribers(topic)


def node_name_of_logger(logger: str) -> str:
    """rclpy logger name -> node name: 'robot1.robot_controller' -> '/robot1/robot_controller'."""
    return '/' + logger.replace('.', '/')


def read_log(lines: Iterable[str]) -> tuple[list[str], set[str], dict[str, list[str]]]:
    """(processes announced, processes ended, node -> processes that logged as it)."""
    started: list[str] = []
    ended: set[str] = set()
    nodes: dict[str, list[str]] = {}
    for line in lines:
        if match := STARTED.match(line):
            started.append(match['process'])
        elif match := ENDED.match(line):
            ended.add(match['process'])
        elif match := NODE_LINE.match(line):
            owners = nodes.setdefault(node_name_of_logger(match['logger']), [])
            if match['process'] not in owners:
                owners.append(match['process'])
    return started, ended, nodes


def _launch_is_up(lines: list[str], present: set[str]) -> bool:
    """Every announced process has logged or ended, and every node a running process
    logged as is in the graph (a process that ended, such as the capstone's spawner,
    takes its node with it)."""
    started, ended, nodes = read_log(lines)
    logged = {process for owners in nodes.values() for process in owners}
    running_nodes = {node for node, owners in nodes.items()
                     if any(process not in ended for process in owners)}
    return bool(started) and all(p in logged or p in ended for p in started) \
        and running_nodes <= present


def probe(package: StudentPackage, launch_file: str, expected_nodes: Iterable[str] = (),
          arguments: Mapping[str, Any] | None = None, timeout: float = 30.0,
          inspect: Callable[[GraphSnapshot], Any] | None = None,
          until_first_process: bool = False) -> LaunchProbe:
    """Start `ros2 launch <package> <launch_file> [arguments]`, wait until it is up
    (see the module docstring), look at the graph, stop it with Ctrl-C.

    `inspect(snapshot)` runs while the launch is still up (e.g. to read
    parameters with labkit.read_parameters); its result is `.inspected`.
    With `until_first_process`, the launch is stopped as soon as it announces a
    process, with no graph read: for a launch that must refuse its arguments, one
    process started already proves it did not, and waiting for a whole system
    to come up would only cost time.
    """
    expected = set(expected_nodes)
    running = launch(package.name, launch_file, launch_arguments=arguments or {},
                     env=package.environment(), cwd=package.workspace)
    try:
        deadline = time.monotonic() + timeout
        last_started: list[str] = []
        steady_since = time.monotonic()
        while running.poll() is None and time.monotonic() < deadline:
            lines = running.lines
            started = read_log(lines)[0]
            if until_first_process and started:
                break
            if started != last_started:
                last_started, steady_since = started, time.monotonic()
            present = set(observer.node_names())
            complete = bool(expected) and expected <= present  # up: no settle needed
            settle = PROCESSES_SETTLED_WITH_NODES_MISSING if expected else PROCESSES_SETTLED
            settled = time.monotonic() - steady_since >= settle
            if _launch_is_up(lines, present) and (settled or complete):
                break
            time.sleep(0.1)
        exited = running.poll() is not None
        snapshot = None if exited or until_first_process else graph()
        inspected = inspect(snapshot) if inspect and snapshot else None
    finally:
        returncode = running.stop()
    lines = running.lines
    started, _, nodes = read_log(lines)
    return LaunchProbe(running.command, lines, returncode, exited, snapshot, started, nodes,
                       inspected)
