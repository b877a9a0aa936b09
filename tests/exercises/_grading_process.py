"""Grade a case in a process of its own, so that a hang inside DDS fails that case, not the run.

Fast DDS 2.14 can deadlock a participant's own discovery threads while it
processes endpoints that go away (eProsima/Fast-DDS#6502: the receive thread
holds the PDP mutex and waits in ResourceEvent::unregister_timer for the event
thread, which waits for that mutex in check_remote_participant_liveliness).
A check's graph observer sees many launches stop, and once it is deadlocked,
the check blocks in C, where no Python timeout reaches it: CI once hung there
(a day-shift probe of 7.4, in rmw_create_client).  So each case is graded in
a child process: a child that has not answered within HANG_GUARD seconds is
killed (labkit's watchdog then stops its launches) and the case fails.  It is
not graded again: a retry would hide the fault it is evidence of (no hang
fired in the last CIs since tools/ddsfix).  Before the kill, the stacks of
every thread of the child (gdb, where installed: Fast DDS's own threads too)
and its Python stacks (faulthandler) go to build/hangs/, and the failure names
the file, so each hang leaves the evidence its cause needs.
"""
from __future__ import annotations

import json
import signal
import subprocess
import sys
from pathlib import Path

import psutil
from labkit.grading.verdict import Verdict

from .._hang_evidence import native_stacks, tail, write_report

#: Seconds; the slowest case takes about 230 s on a loaded 2-core CI worker.
HANG_GUARD = 420.0

_CHILD = """
import json, sys
from pathlib import Path
from labkit import checks
from labkit.grading.student_package import StudentPackage
exercise, workspace, package = sys.argv[1:]
verdict = checks.find(exercise).grade(StudentPackage(Path(workspace), package))
print(json.dumps({'title': verdict.title, 'results': verdict.results}))
"""


def grade(exercise: str, workspace: Path, package: str, guard: float = HANG_GUARD,
          child: str = _CHILD) -> Verdict:
    """The verdict of `exercise` on `package`, graded in a child process (environment
    and ROS domain of this one); raises AssertionError, naming the stacks' file, when
    the child hung."""
    running = subprocess.Popen(
        [sys.executable, '-X', 'faulthandler', '-c', child, exercise, str(workspace), package],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        stdout, stderr = running.communicate(timeout=guard)
    except subprocess.TimeoutExpired:
        report = _hang_report(running)
        raise AssertionError(f'grading {exercise} ({package}) hung for {guard:g} s and was '
                             f'killed; its stacks are in {report}') from None
    assert running.returncode == 0, f'grading {exercise} failed:\n{stdout}{stderr}'
    answer = json.loads(stdout.strip().splitlines()[-1])
    return Verdict(answer['title'], [(met, sentence) for met, sentence in answer['results']])


def _hang_report(running: subprocess.Popen) -> Path:
    """Kill the hung ``running`` child; first write its stacks (every thread, native
    and Python), its processes and the end of its output to a file, returned."""
    try:
        family = [psutil.Process(running.pid), *psutil.Process(running.pid).children(True)]
        processes = [f'{p.pid} {p.status()} {" ".join(p.cmdline())[:200]}' for p in family]
    except psutil.Error:
        processes = []
    native = native_stacks(running.pid)
    running.send_signal(signal.SIGABRT)  # faulthandler prints every thread's Python stack
    try:
        stdout, stderr = running.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        running.kill()
        stdout, stderr = running.communicate()
    return write_report('grading', running.pid, {
        'processes (the child first)': '\n'.join(processes),
        'output (end)': tail(stdout, 40),
        'standard error, with the Python stacks (end)': tail(stderr, 200),
        'native stacks of every thread (gdb)': native})
