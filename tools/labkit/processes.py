"""CPU and memory of the processes a launch started, measured over a window.

`top` shows every process on the machine; a lesson wants the ones of one
launch, named by the node they run, with numbers it can compare before and
after a change.  CPU is the process's own CPU time (user + system) during
the window divided by the window's wall time, so 100 % is one core, as in
`top`; memory is the resident set size (RSS) at the end of the window.
"""
from __future__ import annotations

import os
import time
from collections.abc import Iterable
from dataclasses import dataclass

import psutil

from labkit.background import Background
from labkit.errors import LabkitError


@dataclass(frozen=True)
class ProcessUsage:
    """One process: what it runs, and what it cost during the window."""

    pid: int
    name: str  # the node name given with `-r __node:=`, else the program's name
    command: str
    cpu_percent: float
    rss: int  # bytes

    def __str__(self) -> str:
        return (f'{self.name} (pid {self.pid}): {self.cpu_percent:.1f} % CPU, '
                f'{self.rss / 1e6:.1f} MB RSS')


def process_name(cmdline: list[str]) -> str:
    """`python .../lib/pkg/camera --ros-args -r __node:=front` -> 'front';
    without a node name, the program: the script or module a Python
    interpreter runs (`python .../bin/ros2 launch ...` -> 'ros2'), else its name."""
    for word in cmdline:
        if word.startswith('__node:='):
            return word.partition(':=')[2]
    if not cmdline:
        return '?'
    program = os.path.basename(cmdline[0])
    if program.startswith('python') and len(cmdline) > 1:
        if cmdline[1] == '-m' and len(cmdline) > 2:
            return cmdline[2]
        if not cmdline[1].startswith('-'):
            return os.path.basename(cmdline[1])
    return program


def launch_processes(launch: Background | int) -> list[psutil.Process]:
    """The process of a launch (or any command) and every process it started."""
    pid = launch.pid if isinstance(launch, Background) else launch
    try:
        root = psutil.Process(pid)
        return [root, *root.children(recursive=True)]
    except psutil.NoSuchProcess:
        raise LabkitError(f'process {pid} is not running') from None


def process_usage(processes: Background | Iterable[int], window: float = 3.0,
                  ) -> list[ProcessUsage]:
    """CPU % and RSS of each process over `window` seconds, busiest first.

    Give a running launch (`labkit.launch(...)`: the launch itself and all it
    started) or process IDs.  A process that ends during the window is left out.
    """
    if isinstance(processes, Background):
        targets = launch_processes(processes)
    else:
        targets = [psutil.Process(pid) for pid in processes]
    start = {}
    for process in targets:
        try:
            start[process] = _cpu_seconds(process)
        except psutil.Error:
            continue
    began = time.monotonic()
    time.sleep(window)
    elapsed = time.monotonic() - began
    usage = []
    for process, cpu_before in start.items():
        try:
            with process.oneshot():
                cpu = _cpu_seconds(process) - cpu_before
                rss = process.memory_info().rss
                cmdline = process.cmdline()
        except psutil.Error:
            continue
        usage.append(ProcessUsage(process.pid, process_name(cmdline), ' '.join(cmdline),
                                  100.0 * cpu / elapsed, rss))
    return sorted(usage, key=lambda item: item.cpu_percent, reverse=True)


def _cpu_seconds(process: psutil.Process) -> float:
    times = process.cpu_times()
    return times.user + times.system
