"""assertInStdout / assertInStderr: a process's output contains a text."""
from __future__ import annotations

from ..io_handler import _found
from ..util.proc_lookup import resolveProcesses


def assertDefaultStream() -> str:
    """The stream checked when none is named."""
    return 'stderr'


def assertInStream(proc_output, expected_output, process=None, cmd_args: str | None = None,
                   *, output_filter=None, strict_proc_matching: bool = True,
                   stream: str | None = None) -> None:
    """Fail unless one matching process wrote `expected_output` to `stream`."""
    processes = resolveProcesses(proc_output, process=process, cmd_args=cmd_args,
                                 strict_proc_matching=strict_proc_matching)
    for proc in processes:
        text = proc_output.text(proc, stream)
        if output_filter is not None:
            text = output_filter(text)
        if _found(expected_output, text):
            return
    names = ', '.join(str(p.process_details['name']) for p in processes)
    raise AssertionError(f"Did not find '{expected_output}' in output for any of the "
                         f'matching processes: {names}')


def assertInStdout(proc_output, expected_output, process=None, cmd_args: str | None = None,
                   *, output_filter=None, strict_proc_matching: bool = True) -> None:
    """Fail unless the process wrote `expected_output` to standard output."""
    assertInStream(proc_output, expected_output, process, cmd_args, output_filter=output_filter,
                   strict_proc_matching=strict_proc_matching, stream='stdout')


def assertInStderr(proc_output, expected_output, process=None, cmd_args: str | None = None,
                   *, output_filter=None, strict_proc_matching: bool = True) -> None:
    """Fail unless the process wrote `expected_output` to standard error."""
    assertInStream(proc_output, expected_output, process, cmd_args, output_filter=output_filter,
                   strict_proc_matching=strict_proc_matching, stream='stderr')
