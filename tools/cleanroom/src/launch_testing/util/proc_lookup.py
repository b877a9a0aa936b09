"""Find the processes a test names: by action, by name, and by command-line args."""
from __future__ import annotations

from collections.abc import Iterable

from launch.actions import ExecuteProcess


class NoMatchingProcessException(Exception):
    """No process (or no recorded output) matches what a test asked for."""


def proc_name(process: ExecuteProcess) -> str:
    """The final process name (e.g. 'talker-1'), or the given name before start."""
    details = process.process_details
    if details is not None:
        return str(details['name'])
    return str(process.name)


def _proc_to_name_and_args(process: ExecuteProcess) -> str:
    """'talker-1 --ros-args -r __node:=talker': the name and the arguments after cmd[0]."""
    details = process.process_details
    if details is None:
        return proc_name(process)
    return ' '.join([str(details['name']), *[str(arg) for arg in details['cmd'][1:]]])


def _matches_args(process: ExecuteProcess, cmd_args: str | None) -> bool:
    if cmd_args is None:
        return True
    details = process.process_details
    args = [str(arg) for arg in details['cmd'][1:]] if details is not None else []
    return cmd_args in args


def resolveProcesses(info_obj, *, process=None, cmd_args: str | None = None,
                     strict_proc_matching: bool = True) -> list[ExecuteProcess]:
    """The recorded processes `info_obj` (a proc_info or proc_output) has for the query.

    `process` is an ExecuteProcess action, a name (matched as a substring of the
    process name) or None for all.  Raises NoMatchingProcessException when
    nothing matches, or when several match a name and `strict_proc_matching`.
    """
    recorded: Iterable[ExecuteProcess] = info_obj.processes()
    if process is None:
        found = [p for p in recorded if _matches_args(p, cmd_args)]
        if not found:
            raise NoMatchingProcessException('No data recorded for any process')
        return found
    if isinstance(process, ExecuteProcess):
        if process in list(recorded):
            return [process]
        raise NoMatchingProcessException(
            f'No data recorded for proc {_proc_to_name_and_args(process)}')
    name = str(process)
    recorded = list(recorded)
    found = [p for p in recorded if name in proc_name(p) and _matches_args(p, cmd_args)]
    if not found:  # Jazzy's words, with the processes there are, sorted
        procs = ', '.join(sorted(_proc_to_name_and_args(p) for p in recorded))
        raise NoMatchingProcessException(
            f"Did not find any processes matching name '{name}' and args '{cmd_args}'. "
            f'Procs: {procs}')
    if strict_proc_matching and len(found) > 1:
        names = ', '.join(_proc_to_name_and_args(p) for p in found)
        raise NoMatchingProcessException(
            f"Found multiple processes with name '{name}' and args '{cmd_args}': {names}. "
            'Use strict_proc_matching=False to match all of them')
    return found
