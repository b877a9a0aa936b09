"""assertExitCodes: every (or one) process ended with an allowed exit code."""
from __future__ import annotations

from collections.abc import Iterable

from ..util.proc_lookup import proc_name, resolveProcesses

EXIT_OK = 0
EXIT_SIGINT = 130
EXIT_SIGQUIT = 131
EXIT_SIGKILL = 137
EXIT_FORCED = 1


def assertExitCodes(proc_info, allowable_exit_codes: Iterable[int] = (EXIT_OK,),
                    process=None, cmd_args: str | None = None, *,
                    strict_proc_matching: bool = True) -> None:
    """Fail with 'Proc NAME exited with code N' for a process whose code is not allowed."""
    allowed = list(allowable_exit_codes)
    for proc in resolveProcesses(proc_info, process=process, cmd_args=cmd_args,
                                 strict_proc_matching=strict_proc_matching):
        info = proc_info[proc]
        returncode = getattr(info, 'returncode', None)
        if returncode not in allowed:
            raise AssertionError(f'Proc {proc_name(proc)} exited with code {returncode}')
