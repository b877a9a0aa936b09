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
Which `ros2` that is, `find_ros2`, is speccheck's (it starts launches too).
"""
from __future__ import annotations

import functools
import subprocess
import time
from collections.abc import Iterable

from speccheck.launch_command import find_ros2

__all__ = ['find_ros2', 'missing_from_daemon']

#: Seconds between two looks at the daemon's graph.
POLL = 0.2


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
