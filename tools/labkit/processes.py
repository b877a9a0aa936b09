"""CPU and memory of the processes a launch started, measured over a window.

`top` shows every process on the machine; a lesson wants the ones of one
launch, named by the node they run, with numbers it can compare before and
after a change.  CPU is the process's own CPU time (user + system) during
the window divided by the window's wall time, so 100 % is one core, as in
`top`; memory is the resident set size (RSS), averaged over samples taken
every `SAMPLE_INTERVAL` seconds during the window.  One sample is not enough:
a process that handles large messages allocates and frees several of them a
second (each 2.7 MB frame of lesson 6.10 is its own allocation), so its RSS
at one instant can be off by a few of them.
"""
from __future__ import annotations

import os
import time
from collections.abc import Iterable
from dataclasses import dataclass

import psutil

from labkit.background import Background
from labkit.errors import LabkitError

#: Seconds between two RSS samples of each process during the window.
SAMPLE_INTERVAL = 0.1


@dataclass(frozen=True)
class ProcessUsage:
    """One process: what it runs, and what it cost during the window."""

    pid: int
    name: str  # the node name given with `-r __node:=`, else the program's name
    command: str
    cpu_percent: float
    rss: int  # bytes, mean over the window

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
    """CPU % and mean RSS of each process over `window` seconds, busiest first.

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
    samples: dict[psutil.Process, list[int]] = {process: [] for process in start}
    began = time.monotonic()
    deadline = began + window
    while True:
        _sample_rss(samples)
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            break
        time.sleep(min(SAMPLE_INTERVAL, remaining))
    elapsed = time.monotonic() - began
    usage = []
    for process, cpu_before in start.items():
        try:
            with process.oneshot():
                cpu = _cpu_seconds(process) - cpu_before
                cmdline = process.cmdline()
        except psutil.Error:
            continue
        rss = samples[process]
        if not rss:
            continue
        usage.append(ProcessUsage(process.pid, process_name(cmdline), ' '.join(cmdline),
                                  100.0 * cpu / elapsed, round(sum(rss) / len(rss))))
    return sorted(usage, key=lambda item: item.cpu_percent, reverse=True)


def _sample_rss(samples: dict[psutil.Process, list[int]]) -> None:
    """One RSS sample of each process still running."""
    for process, taken in samples.items():
        try:
            taken.append(process.memory_info().rss)
        except psutil.Error:
            continue


def _cpu_seconds(process: psutil.Process) -> float:
    times = process.cpu_times()
    return times.user + times.system
