"""Checks of lesson 7.1 (The specification, of the capstone).

Exercise 7.1.1 grades a spec file by what it does, as exercise 6.8.1 does:
the student's spec for the new requirement R9 (a third robot, turtle3) is
run through `speccheck live`, as their terminal would run it,
against the capstone with `robot_count:=3`, which meets R9 (it must pass),
then against two systems that do not: the capstone with two robots, and
one where turtle3 runs with turtle4's configuration (both must fail).
The capstone builds its robots in an OpaqueFunction, which the static check
cannot see into, so every stage is a running check.

A run whose wait for turtle3's nodes ran out in a system that does run them
(a busy machine) is repeated with a longer wait, and a system that never
starts is reported as such, never as a defect the spec caught (spec_run).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from labkit.grading import spec_run
from labkit.grading.capstone import robot_nodes
from labkit.grading.exercise import SNIPPETS, Exercise
from labkit.grading.spec_run import SpecRun
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

SPEC = 'specs/ex71_third_robot.spec.yaml'
BOOK_PACKAGE = 'capstone_bringup'
SYSTEM = 'capstone.launch.py'
DEFECT = SNIPPETS / 'ch07_defects' / 'turtle3_other_config.launch.py'
SHOWN_FINDINGS = 6
#: a ROS name in a finding; the capstone's all start with a turtle or turtlesim
ROS_NAME = re.compile(r'(?<![\w.])/[A-Za-z_][\w/]*')
IN_THE_SYSTEM = re.compile(r'^/(turtle\d+|turtlesim)(/|$)')


@dataclass(frozen=True)
class System:
    """A system the spec is run against: how to start it and what is wrong with it."""

    launch: tuple[str, ...]  # speccheck's arguments after the spec
    shown: str
    robots: int  # it runs turtle1 ... turtle<robots>
    defect: str = ''  # '' for the system that meets R9
    need: str = ''  # what the spec must say to catch the defect

    def runs(self, node: str) -> bool:
        """Whether `node` (a fully qualified name) is one of this system's robot nodes."""
        return node in robot_nodes(*(f'turtle{n}' for n in range(1, self.robots + 1)))


MEETS_R9 = System(('--launch', BOOK_PACKAGE, SYSTEM, 'robot_count:=3'),
                  f'{SYSTEM} robot_count:=3', robots=3)
DEFECTS = (
    System(('--launch', BOOK_PACKAGE, SYSTEM, 'robot_count:=2'), f'{SYSTEM} robot_count:=2', 2,
           'there is no third robot', "name turtle3's nodes (/turtle3/...) in your spec"),
    System((str(DEFECT),), DEFECT.name, 3,
           "turtle3 runs with turtle4's configuration (its route along the bottom edge, "
           'stop_distance 1.0)',
           "give turtle3's waypoints and stop_distance the values R9 fixes, not only types"),
)


def run_speccheck(package: StudentPackage, system: System) -> SpecRun:
    """The student's spec against `system`, running, in their workspace's environment."""
    spec = package.source / SPEC
    return spec_run.run_live(
        package, spec, list(system.launch),
        lambda target: f'speccheck live {package.shown(spec)} {" ".join(target)}',
        system.runs, system.shown)


def _why(failed: list[str]) -> str:
    names = [name for line in failed for name in ROS_NAME.findall(line)]
    if any(not IN_THE_SYSTEM.match(name) for name in names):
        return ('your spec names nodes or topics the system does not have: write each name '
                'fully qualified, with its namespace (/turtle3/...)')
    return 'your spec asks for something R9 does not say (compare with config/turtle3.yaml)'


def _passes_the_system(verdict: Verdict, package: StudentPackage) -> bool:
    run = run_speccheck(package, MEETS_R9)
    if run.returncode == 2:
        return verdict.fail(f'`{run.command}` could not read the spec: {run.error}').passed
    if run.unjudged:
        return verdict.fail(run.unjudged).passed
    findings = run.shown_findings(SHOWN_FINDINGS)
    return verdict.expect(
        run.returncode == 0 and not run.failed,
        f'the running check of {MEETS_R9.shown}, which meets R9, passes with your spec',
        f'the running check of {MEETS_R9.shown}, which meets R9, fails with your spec: '
        f'{_why(run.failed)}. `{run.command}` reported:\n      {findings}')


def _catches(verdict: Verdict, package: StudentPackage, system: System) -> None:
    run = run_speccheck(package, system)
    if run.unjudged:
        verdict.fail(run.unjudged)
        return
    first = run.failed[0] if run.failed else run.error
    verdict.expect(
        run.returncode == 1 and bool(run.failed),
        f'the running check catches {system.shown} ({system.defect}): {first}',
        f'your spec passes {system.shown}, where {system.defect}: {system.need}')


def check_third_robot(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The student's spec passes the capstone with three robots and fails both defects."""
    spec = package.source / SPEC
    if not spec.is_file():
        return verdict.fail(f'{package.shown(spec)} does not exist: run '
                            "labkit.exercises.setup('ex71_third_robot') to create the starter")
    if not _passes_the_system(verdict, package):
        return verdict
    for system in DEFECTS:
        _catches(verdict, package, system)
    return verdict


EXERCISES = (
    Exercise('ex71_third_robot', "Exercise 7.1.1 (the third robot's requirement as a spec)",
             (SPEC,), check_third_robot),
)
