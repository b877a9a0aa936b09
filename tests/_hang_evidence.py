"""The evidence a hung process leaves before it is killed: its native stacks.

A test that gives up on a process (a node that ignores Ctrl+C, a grading child
blocked inside DDS) kills it; without its stacks the cause is lost.  gdb, where
installed, prints every thread's native backtrace (Fast DDS's own threads too);
the Python stacks come from faulthandler in the process itself (started with
``-X faulthandler`` or PYTHONFAULTHANDLER=1), printed when it gets SIGABRT.
Reports go to build/hangs/, one file per hang, named in the test's failure.
"""
from __future__ import annotations

import shutil
import subprocess
import time
from pathlib import Path

from textbook import paths

#: Where the stacks of a hung process are kept.
HANGS = paths.BUILD / 'hangs'


def native_stacks(pid: int) -> str:
    """Every thread's native backtrace of process ``pid`` (gdb), or why there is none."""
    if not shutil.which('gdb'):
        return 'gdb is not installed'
    try:
        return subprocess.run(['gdb', '-p', str(pid), '-batch', '-ex', 'thread apply all bt 40'],
                              capture_output=True, text=True, timeout=120, check=False).stdout
    except subprocess.TimeoutExpired:
        return 'gdb did not answer within 120 s'


def write_report(kind: str, pid: int, sections: dict[str, str]) -> Path:
    """A new file in build/hangs/ holding ``sections`` (title: text), returned."""
    HANGS.mkdir(parents=True, exist_ok=True)
    report = HANGS / f'{kind}-{pid}-{time.strftime("%Y%m%d-%H%M%S")}.txt'
    report.write_text('\n\n'.join(f'== {title}\n{text}' for title, text in sections.items()))
    return report


def tail(output: str | bytes | None, lines: int = 15) -> str:
    """The last ``lines`` lines of ``output``, each ending in a newline."""
    text = output.decode(errors='replace') if isinstance(output, bytes) else output or ''
    return ''.join(line + '\n' for line in text.splitlines()[-lines:])
