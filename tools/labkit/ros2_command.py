"""The `ros2` command of the active environment, and what it sees of the graph.

On Jazzy, `ros2 node list`, `ros2 param get`, `ros2 node info` and
`ros2 topic info` ask the ROS 2 daemon, a background process that the first
such command starts and that discovers the graph on its own.  Right after a
launch, or right after the daemon started, it may not have seen a node that
labkit's observer already sees, and the command answers "Node not found"
(or lists nothing).  A lesson waits for the state it shows, so
`Background.wait_for_nodes` also waits until the daemon lists what the
observer saw.  The clean room's `ros2` has a daemon too (same words, same
hand-over); a `ros2` without the `daemon` verb has nothing to wait for.
"""
from __future__ import annotations

import functools
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Iterable, Mapping
from pathlib import Path

#: Seconds between two looks at the daemon's graph.
POLL = 0.2


def find_ros2(env: Mapping[str, str] | None = None) -> str:
    """The `ros2` a terminal with this environment would run.

    Falls back to the one next to this Python (a project venv that is not on
    PATH, e.g. in a notebook kernel started directly from .venv).
    """
    path = (env if env is not None else os.environ).get('PATH', os.defpath)
    found = shutil.which('ros2', path=path)
    if found:
        return found
    beside = Path(sys.executable).parent / 'ros2'
    if beside.exists():
        return str(beside)
    raise FileNotFoundError('no `ros2` command found on PATH nor next to '
                            f'{sys.executable}; is ROS 2 (or the project venv) set up?')


@functools.cache
def _has_daemon(ros2: str) -> bool:
    """Whether this `ros2` has the `daemon` verb (Jazzy's ros2cli and the clean room have)."""
    found = subprocess.run([ros2, 'daemon', 'status'], capture_output=True, text=True,
                           check=False)
    return found.returncode == 0


def _listed(ros2: str, *verb: str) -> set[str]:
    done = subprocess.run([ros2, *verb], capture_output=True, text=True, check=False)
    return set(done.stdout.split()) if done.returncode == 0 else set()


def missing_from_daemon(ros2: str, nodes: Iterable[str], topics: Iterable[str] = (),
                        timeout: float = 20.0) -> list[str]:
    """Wait until the daemon lists `nodes` and `topics`; return what it still lacks.

    Starts the daemon if it is not running, as the next `ros2` command would.
    Returns [] at once when this `ros2` has no daemon.
    """
    if not _has_daemon(ros2):
        return []
    subprocess.run([ros2, 'daemon', 'start'], capture_output=True, check=False)
    deadline = time.monotonic() + timeout
    while True:
        missing = sorted(set(nodes) - _listed(ros2, 'node', 'list', '--all'))
        if topics:
            missing += sorted(set(topics) - _listed(ros2, 'topic', 'list'))
        if not missing or time.monotonic() >= deadline:
            return missing
        time.sleep(POLL)
