"""Checks of lesson 6.14 (From a specification to a system).

Exercise 6.14.1 grades a launch file against a spec: the student's launch
file is judged by the book's spec checker, run as their terminal would run
it (`speccheck`), against dock_watch_pkg's
specs/dock_watch_robot.spec.yaml.  The spec describes the default arguments
only, so the file is also checked with `robot:=rover` against the same spec
with /rover/ names: a namespace written in as text passes the defaults and
fails there.  Static checks first (fast, and they name most mistakes), then
the running checks, which start the student's launch and ask the graph;
the first stage that fails ends the check, naming what it found.
"""
from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

from labkit.grading import requirements, spec_run
from labkit.grading.exercise import Exercise
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

LAUNCH = 'launch/ex614_dock_watch.launch.py'
BOOK_PACKAGE = 'dock_watch_pkg'
SPEC = 'dock_watch_robot.spec.yaml'
ROBOT, OTHER_ROBOT = 'scout', 'rover'
WINDOW = '3'  # seconds the running check measures rates over
SHOWN_FINDINGS = 6


@dataclass(frozen=True)
class Stage:
    """One speccheck run: static or live, with or without `robot:=rover`."""

    mode: str
    robot: str

    @property
    def arguments(self) -> list[str]:
        return [] if self.robot == ROBOT else [f'robot:={self.robot}']

    def command(self, package: StudentPackage) -> str:
        spec = SPEC if self.robot == ROBOT else f'{SPEC} (its names with /{self.robot}/)'
        return ' '.join(['speccheck', self.mode, spec, '--launch', package.name,
                         Path(LAUNCH).name, *self.arguments])


STAGES = (Stage('static', ROBOT), Stage('static', OTHER_ROBOT),
          Stage('live', ROBOT), Stage('live', OTHER_ROBOT))


def book_spec(env: dict[str, str]) -> Path | None:
    """dock_watch_robot.spec.yaml in the share folder of the sourced dock_watch_pkg."""
    for prefix in filter(None, env.get('AMENT_PREFIX_PATH', '').split(os.pathsep)):
        candidate = Path(prefix) / 'share' / BOOK_PACKAGE / 'specs' / SPEC
        if candidate.is_file():
            return candidate
    return None


def _advice(stage: Stage, failed: list[str]) -> str:
    if stage.robot != ROBOT:
        return (f'with robot:={stage.robot} every node must run in /{stage.robot}/ '
                '(R9): take the namespace from the argument robot, not from the text '
                f"'{ROBOT}'")
    if any(line.startswith('argument robot') for line in failed):
        return "R9 asks for a launch argument robot with the default 'scout'"
    if any(line.startswith('node ') for line in failed):
        return 'every node of the spec must run in /scout/ (R9), each with its parameters'
    if any(line.startswith('topic ') for line in failed):
        return ('R9 puts the topics in the namespace too: no remapping to an absolute '
                'name (/battery_state)')
    return 'the system must keep meeting R1 to R8 as well'


def _run_stage(verdict: Verdict, package: StudentPackage, stage: Stage, spec: Path,
               env: dict[str, str]) -> bool:
    target = ['--launch', package.name, Path(LAUNCH).name, *stage.arguments]
    if stage.mode == 'live':
        target += ['--window', WINDOW]
    run = spec_run.run_speccheck(package, stage.mode, spec, target,
                                 f'`{stage.command(package)}`', env)
    if run.returncode == 2:
        return verdict.fail(f'{run.command} could not run: {run.error}').passed
    findings = run.shown_findings(SHOWN_FINDINGS)
    return verdict.expect(
        run.returncode == 0 and not run.failed,
        f'{run.command}: {run.summary}',
        f'{run.command} finds requirements not met ({_advice(stage, run.failed)}):\n      '
        f'{findings}')


def check_dock_watch_robot(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The student's launch file meets version 3 of the spec, for robot scout and rover."""
    if not requirements.files_installed(verdict, package):
        return verdict
    env = package.environment()
    spec = book_spec(env)
    if spec is None:
        return verdict.fail(f'{BOOK_PACKAGE}/specs/{SPEC} is not installed in the sourced '
                            f"workspace: build the book's {BOOK_PACKAGE} and source "
                            'install/setup.bash')
    with tempfile.TemporaryDirectory(prefix='ex614_') as scratch:
        other = Path(scratch) / f'{OTHER_ROBOT}.spec.yaml'
        other.write_text(spec.read_text().replace(f'/{ROBOT}/', f'/{OTHER_ROBOT}/'))
        for stage in STAGES:
            stage_spec = spec if stage.robot == ROBOT else other
            if not _run_stage(verdict, package, stage, stage_spec, env):
                break
    return verdict


EXERCISES = (
    Exercise('ex614_dock_watch', 'Exercise 6.14.1 (the specification changes: one robot '
             'in its namespace)', (LAUNCH,), check_dock_watch_robot),
)
