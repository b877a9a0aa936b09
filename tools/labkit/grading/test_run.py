"""Grading a test the student wrote: run it as their terminal would, against the
working system and against broken versions of it.

A test earns its keep by passing on the working system and failing on every
broken one; a test that passes on a broken system is named with what was
broken, so the student learns what their test does not look at.  The checks
of 6.15 and 7.3 differ only in the system and its defects.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Protocol

from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

RUN_TIMEOUT = 300.0  # seconds; only stops a hung run, never a speed limit
VERDICT_LINE = re.compile(r'^(\w+) \([\w.]+\) \.\.\. (ok|FAIL|ERROR)$', re.M)
REASON_LINE = re.compile(r'^(\w+(?:\.\w+)*(?:Error|Exception): .*)$', re.M)


class PlantedDefect(Protocol):
    """A planted defect: what it breaks and what a test must do to notice it."""

    what: str  # completes 'a system whose ...'
    hint: str


def run_test(test_file: Path, env: dict[str, str], cwd: Path) -> subprocess.CompletedProcess:
    """`launch_test FILE`, as the student's terminal runs it."""
    launch_test = shutil.which('launch_test', path=env.get('PATH')) or 'launch_test'
    return subprocess.run([launch_test, str(test_file)], env=env, cwd=cwd,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          timeout=RUN_TIMEOUT, check=False)


def summary(result: subprocess.CompletedProcess) -> str:
    """The first test that did not pass, with the first reason given, from the report.

    Only the first: it decided the run (active tests run, and report, before the
    post-shutdown ones).  What failed after it can depend on the moment of the
    shutdown (a respawning node that crashes at every start is dead or starting),
    and a verdict must read the same on every run and on every ROS 2 install.
    """
    failed = [f'{name} {outcome}' for name, outcome in VERDICT_LINE.findall(result.stderr)
              if outcome != 'ok']
    reasons = REASON_LINE.findall(result.stderr)
    if not failed:
        tail = [line for line in (result.stderr or result.stdout).splitlines()
                if line.strip()][-3:]
        return 'no test failed; the run ended with: ' + (' | '.join(tail) or 'nothing')
    return failed[0] + (f' ({reasons[0]})' if reasons else '')


def grade_against_defects(package: StudentPackage, verdict: Verdict, *, test_file: Path,
                          working: str, no_test_hint: str, broken: Sequence[PlantedDefect],
                          broken_prefix: Callable[[PlantedDefect, Path], Path]) -> Verdict:
    """Run the student's `test_file` on the working system (`working` names it), then
    once per broken system, each seen through the prefix `broken_prefix(system, folder)`
    puts first on AMENT_PREFIX_PATH."""
    env = package.environment()
    shown = f'`launch_test {package.shown(test_file)}`'
    result = run_test(test_file, env, package.workspace)
    if not VERDICT_LINE.search(result.stderr):
        return verdict.fail(f'{shown} runs no test: write an active test class '
                            f'(unittest.TestCase) {no_test_hint}, and a post-shutdown one '
                            f'({summary(result)})')
    if not verdict.expect(
            result.returncode == 0,
            f'{shown} passes on the {working}',
            f'{shown} must pass on the {working} first: {summary(result)}'):
        return verdict
    with tempfile.TemporaryDirectory(prefix='broken_') as scratch:
        for system in broken:
            prefix = broken_prefix(system, Path(scratch))
            broken_env = dict(env, AMENT_PREFIX_PATH=os.pathsep.join(
                [str(prefix), env.get('AMENT_PREFIX_PATH', '')]))
            result = run_test(test_file, broken_env, package.workspace)
            verdict.expect(
                result.returncode != 0,
                f'{shown} fails on a system whose {system.what}: {summary(result)}',
                f'{shown} passes on a system whose {system.what}: {system.hint}')
    return verdict
