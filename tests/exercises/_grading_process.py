"""Grade a case in a process of its own, so that a hang inside DDS costs a retry, not the run.

Fast DDS 2.14 can deadlock a participant's own discovery threads while it
processes endpoints that go away (eProsima/Fast-DDS#6502: the receive thread
holds the PDP mutex and waits in ResourceEvent::unregister_timer for the event
thread, which waits for that mutex in check_remote_participant_liveliness).
A check's graph observer sees many launches stop, and once it is deadlocked,
the check blocks in C, where no Python timeout reaches it: CI once hung there
(a day-shift probe of 7.4, in rmw_create_client).  So each case is graded in
a child process: a child that has not answered within HANG_GUARD seconds is
killed (labkit's watchdog then stops its launches) and the case is graded once
more, which the test log says.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from labkit.grading.verdict import Verdict

#: Seconds; the slowest case takes about 230 s on a loaded 2-core CI worker.
HANG_GUARD = 420.0
ATTEMPTS = 2

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
    and ROS domain of this one); raises AssertionError when every attempt hung."""
    for attempt in range(1, ATTEMPTS + 1):
        try:
            done = subprocess.run([sys.executable, '-c', child, exercise, str(workspace), package],
                                  capture_output=True, text=True, timeout=guard, check=False)
        except subprocess.TimeoutExpired as hung:
            print(f'grading attempt {attempt} of {exercise} hung for {guard:g} s and was '
                  f'killed; its output ended with:\n{_tail(hung.stdout)}{_tail(hung.stderr)}')
            continue
        assert done.returncode == 0, f'grading {exercise} failed:\n{done.stdout}{done.stderr}'
        answer = json.loads(done.stdout.strip().splitlines()[-1])
        return Verdict(answer['title'], [(met, sentence) for met, sentence in answer['results']])
    raise AssertionError(f'grading {exercise} hung {ATTEMPTS} times ({guard:g} s each)')


def _tail(output: str | bytes | None, lines: int = 15) -> str:
    text = output.decode(errors='replace') if isinstance(output, bytes) else output or ''
    return ''.join(line + '\n' for line in text.splitlines()[-lines:])
