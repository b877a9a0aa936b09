"""Find and stop processes a run left behind.

A process belongs to a run when its environment carries the run's lease
token (see isolation.LEASE_VAR), which survives new sessions and reparenting
where a process-tree search would lose track.
"""
from __future__ import annotations

import time
from collections.abc import Iterable

import psutil

from .isolation import LEASE_VAR


def _protected() -> set[int]:
    """This process and its ancestors: never ours to kill."""
    me = psutil.Process()
    return {me.pid, *(p.pid for p in me.parents())}


def find_processes(tokens: Iterable[str]) -> list[psutil.Process]:
    """Live processes whose environment holds one of ``tokens``."""
    wanted = set(tokens)
    protected = _protected()
    found = []
    for proc in psutil.process_iter():
        if proc.pid in protected:
            continue
        try:
            if proc.environ().get(LEASE_VAR) in wanted and proc.status() != psutil.STATUS_ZOMBIE:
                found.append(proc)
        except (psutil.NoSuchProcess, psutil.AccessDenied, psutil.ZombieProcess):
            continue
    return found


def describe(proc: psutil.Process) -> str:
    try:
        return f"pid {proc.pid}: {' '.join(proc.cmdline()) or proc.name()}"
    except psutil.Error:
        return f'pid {proc.pid}'


def is_ros2_daemon(proc: psutil.Process) -> bool:
    """The ROS 2 daemon (`ros2 daemon`, `--name ros2-daemon`) that Jazzy's `ros2`
    starts and leaves running on purpose, as on a student's machine."""
    try:
        return '--name' in (cmdline := proc.cmdline()) and 'ros2-daemon' in cmdline
    except psutil.Error:
        return False


def reap(tokens: Iterable[str], grace: float = 5.0) -> list[str]:
    """Stop every process of ``tokens`` still alive; returns what had to be killed.

    Waits ``grace`` seconds first, so processes that are already shutting
    down (e.g. killed by a watchdog when their kernel died) are not counted.
    A ROS 2 daemon is stopped too but not returned: `ros2` started it for the
    run's domain and keeps it by design.
    """
    tokens = list(tokens)
    deadline = time.monotonic() + grace
    left = find_processes(tokens)
    while any(not is_ros2_daemon(p) for p in left) and time.monotonic() < deadline:
        time.sleep(0.2)
        left = find_processes(tokens)
    if not left:
        return []
    names = [describe(p) for p in left if not is_ros2_daemon(p)]
    for proc in left:
        try:
            proc.terminate()
        except psutil.Error:
            pass
    _, alive = psutil.wait_procs(left, timeout=3)
    for proc in alive:
        try:
            proc.kill()
        except psutil.Error:
            pass
    psutil.wait_procs(alive, timeout=3)
    return names

