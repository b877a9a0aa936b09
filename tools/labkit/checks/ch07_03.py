"""Checks of lesson 7.3 (Testing and operating it).

Exercise 7.3.1 grades a fault test, so the check runs it, as lesson 6.15's
check does (both use labkit.grading.test_run): `launch_test` on the
student's test file against the working capstone, then against broken
versions of capstone_bringup.  A test earns its keep by passing on the first
and failing on every other; a test that passes on a broken system is named
with what was broken, so the student learns what their test does not look at.

A broken version is capstone_bringup seen through a prefix of its own put
first on AMENT_PREFIX_PATH: its share folder is a copy of the installed one
with one file replaced by a planted defect from snippets/ch07_defects/
(capstone_bringup has no code, so a share folder is all of it).  The
student's test includes capstone.launch.py through FindPackageShare, which
finds the broken copy first, without any change to the test.
"""
from __future__ import annotations

import os
import shutil
from dataclasses import dataclass
from functools import partial
from pathlib import Path

from labkit.grading.exercise import SNIPPETS, Exercise
from labkit.grading.student_package import StudentPackage
from labkit.grading.test_run import grade_against_defects
from labkit.grading.verdict import Verdict

TEST = 'test/test_ex73_capstone_fault.py'
BOOK_PACKAGE = 'capstone_bringup'
LAUNCH_FILE = 'capstone.launch.py'
DEFECTS = SNIPPETS / 'ch07_defects'


@dataclass(frozen=True)
class BrokenCapstone:
    """capstone_bringup with one installed file replaced, and what a test must notice."""

    replaced: str  # path inside share/capstone_bringup
    defect: str  # file name in snippets/ch07_defects/
    what: str  # completes 'a system whose ...'
    hint: str


BROKEN = (
    BrokenCapstone('launch/robot.launch.py', 'robot_monitor_not_critical.launch.py',
                   "safety monitor's exit does not shut the launch down",
                   'after the fault, wait for the reaction: the launch shutting down, and why '
                   '(an OnShutdown handler in generate_test_description can record '
                   'event.reason for the tests)'),
    BrokenCapstone('config/turtle1.yaml', 'turtle1_sensor_crashes.yaml',
                   'wall sensor crashes at every start (turtle1 never gets a wall reading)',
                   'before planting the fault, wait until the system works, for example for '
                   'messages on /turtle1/wall_reading (launch_testing_ros.WaitForTopics)'),
)


def installed_share(env: dict[str, str]) -> Path | None:
    """The share folder of the sourced capstone_bringup."""
    for prefix in filter(None, env.get('AMENT_PREFIX_PATH', '').split(os.pathsep)):
        share = Path(prefix) / 'share' / BOOK_PACKAGE
        if (share / 'launch' / LAUNCH_FILE).is_file():
            return share
    return None


def broken_prefix(installed: Path, system: BrokenCapstone, folder: Path) -> Path:
    """A prefix holding capstone_bringup with `system`'s defect planted in its share."""
    prefix = folder / Path(system.defect).stem.removesuffix('.launch')
    index = prefix / 'share' / 'ament_index' / 'resource_index' / 'packages'
    index.mkdir(parents=True)
    (index / BOOK_PACKAGE).touch()
    share = prefix / 'share' / BOOK_PACKAGE
    shutil.copytree(installed, share)
    shutil.copyfile(DEFECTS / system.defect, share / system.replaced)
    return prefix


def check_capstone_fault_test(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The student's fault test passes on the capstone and fails on each broken one."""
    test_file = package.source / TEST
    if not test_file.is_file():
        return verdict.fail(f'{package.shown(test_file)} does not exist: run '
                            "labkit.exercises.setup('ex73_capstone_fault_test')")
    installed = installed_share(package.environment())
    if installed is None:
        return verdict.fail(f'{BOOK_PACKAGE} is not installed in the sourced workspace: '
                            f"build the book's {BOOK_PACKAGE} and source install/setup.bash")
    return grade_against_defects(
        package, verdict, test_file=test_file,
        working=f'working capstone ({LAUNCH_FILE} as shipped)',
        no_test_hint='that plants the fault and waits for the reaction', broken=BROKEN,
        broken_prefix=partial(broken_prefix, installed))


EXERCISES = (
    Exercise('ex73_capstone_fault_test', 'Exercise 7.3.1 (a fault test for the capstone)',
             (TEST,), check_capstone_fault_test),
)
