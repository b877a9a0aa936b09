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
    """A process that does nothing until the launch stops it, so the launch stays up."""
    return ExecuteProcess(
        cmd=[sys.executable, '-c', _SLEEP_UNTIL_SIGNALLED],
        name='keep_alive_proc', sigterm_timeout='1')


__all__ = ['KeepAliveProc', 'NoMatchingProcessException', 'resolveProcesses']
