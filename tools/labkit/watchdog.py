"""Sidecar that kills a background launch when the notebook kernel dies.

    python .../labkit/watchdog.py OWNER_PID PGID

labkit starts one per background process (by path: it needs only psutil and rclhelpers),
in a session of its own so that whatever kills the kernel (a crash, a
restart, a cell timeout that kills the kernel's process group) does not
kill the watchdog too.  It is a child of the kernel, so when the kernel is
gone its parent changes; it then stops the process group PGID (SIGINT,
SIGTERM, SIGKILL) and exits.  It also exits by itself once the group is
empty, e.g. after `run.stop()`.
"""
from __future__ import annotations

import os
import signal
import sys
import time

from rclhelpers import processes
from rclhelpers.processes import group_members

POLL = 0.2
#: (signal, seconds to wait for the group to go away after sending it)
ESCALATION = ((signal.SIGINT, 3.0), (signal.SIGTERM, 2.0), (signal.SIGKILL, 2.0))


def stop_group(pgid: int, escalation: tuple = ESCALATION) -> bool:
    """rclhelpers.processes.stop_group with the watchdog's escalation by default."""
    return processes.stop_group(pgid, escalation)


def watch(owner_pid: int, pgid: int) -> int:
    """Wait for the owner to die (then stop the group) or the group to end."""
    while True:
        if os.getppid() != owner_pid:
            return 0 if stop_group(pgid) else 1
        if not group_members(pgid):
            return 0
        time.sleep(POLL)


def main(argv: list[str]) -> int:
    if len(argv) != 2 or not all(arg.isdigit() for arg in argv):
        print('usage: watchdog.py OWNER_PID PGID', file=sys.stderr)
        return 2
    handle_signals()
    return watch(int(argv[0]), int(argv[1]))


def handle_signals() -> None:
    """labkit's stop() ends the watchdog with SIGTERM, at once: the watchdog may be
    exiting by itself already (its group just emptied), and a SystemExit raised in
    the interpreter's shutdown is printed as `Exception ignored ...` into the
    notebook cell (seen on Jazzy in 6.13).  Ctrl-C in the kernel is not for it."""
    signal.signal(signal.SIGTERM, lambda *_: os._exit(0))
    signal.signal(signal.SIGINT, signal.SIG_IGN)


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
