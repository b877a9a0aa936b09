"""Helpers of launch_testing: process lookup and a process that keeps a launch alive."""
from __future__ import annotations

import sys

from launch.actions import ExecuteProcess

from .proc_lookup import NoMatchingProcessException, resolveProcesses

# exits 0 on SIGINT/SIGTERM, so assertExitCodes over all processes still passes
_SLEEP_UNTIL_SIGNALLED = (
    'import signal, sys\n'
    'for s in (signal.SIGINT, signal.SIGTERM):\n'
    '    signal.signal(s, lambda *_: sys.exit(0))\n'
    'while True:\n'
    '    signal.pause()\n')


def KeepAliveProc() -> ExecuteProcess:  # noqa: N802 - Jazzy's name
    """A process that does nothing until the launch stops it, so the launch stays up.

    The shell starts Python with SIGINT ignored (an ignored signal stays ignored
    across exec), so a shutdown that comes while Python is still starting is
    not a KeyboardInterrupt exit; the handlers above take over once installed,
    and SIGTERM follows a missed SIGINT after sigterm_timeout.
    """
    return ExecuteProcess(
        cmd=['sh', '-c', 'trap "" INT; exec "$0" -c "$1"', sys.executable,
             _SLEEP_UNTIL_SIGNALLED],
        name='keep_alive_proc', sigterm_timeout='1')


__all__ = ['KeepAliveProc', 'NoMatchingProcessException', 'resolveProcesses']
