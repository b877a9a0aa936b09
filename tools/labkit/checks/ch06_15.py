"""Checks of lesson 6.15 (Integration tests for launch files).

Exercise 6.15.1 grades a test, so the check runs it: `launch_test` on the
student's test file, as their terminal would, once against the working
dock_watch_pkg and once against each broken version of it.  A test earns
its keep by passing on the first and failing on every other; a test that
passes on a broken system is named with what was broken, so the student
learns what their test does not look at.

A broken version is dock_watch_pkg seen through a prefix of its own put
first on AMENT_PREFIX_PATH: its share folder is a copy of the installed one
with dock_watch_v2.launch.py replaced by a planted defect from the
package's test/defects/, and its lib folder is the installed one.  The
student's test finds it as it finds the real package (FindPackageShare),
without any change to the test.
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

TEST = 'test/test_ex615_dock_watch.py'
BOOK_PACKAGE = 'dock_watch_pkg'
LAUNCH_FILE = 'dock_watch_v2.launch.py'
DEFECTS = SNIPPETS / BOOK_PACKAGE / 'test' / 'defects'


@dataclass(frozen=True)
class BrokenSystem:
    """dock_watch_pkg with one planted defect, and what a test must notice."""

    defect: str  # file name in test/defects/
    what: str  # completes 'a system whose ...'
    hint: str

    @property
    def launch_file(self) -> Path:
        return DEFECTS / self.defect


BROKEN = (
    BrokenSystem('deaf_monitor.launch.py',
                 'battery_monitor listens on the wrong topic (nothing reaches /battery_low)',
                 "wait for something only the whole chain produces, such as the planner's "
                 "'First report' (proc_output.assertWaitFor) or messages on /battery_low"),
    BrokenSystem('dock_in_cm.launch.py',
                 'dock_planner stops at start (its dock_x is out of range)',
                 'check how every process ended: a post-shutdown test with '
                 'launch_testing.asserts.assertExitCodes(proc_info)'),
)


def installed_prefix(env: dict[str, str]) -> Path | None:
    """The install prefix of the sourced dock_watch_pkg."""
    for prefix in filter(None, env.get('AMENT_PREFIX_PATH', '').split(os.pathsep)):
        if (Path(prefix) / 'share' / BOOK_PACKAGE / 'launch' / LAUNCH_FILE).is_file():
            return Path(prefix)
    return None


def broken_prefix(installed: Path, system: BrokenSystem, folder: Path) -> Path:
    """A prefix holding dock_watch_pkg with `system`'s launch file instead of the real one."""
    prefix = folder / system.defect.removesuffix('.launch.py')
    index = prefix / 'share' / 'ament_index' / 'resource_index' / 'packages'
    index.mkdir(parents=True)
    (index / BOOK_PACKAGE).touch()
    share = prefix / 'share' / BOOK_PACKAGE
    shutil.copytree(installed / 'share' / BOOK_PACKAGE, share)
    shutil.copyfile(system.launch_file, share / 'launch' / LAUNCH_FILE)
    (prefix / 'lib').mkdir()
    (prefix / 'lib' / BOOK_PACKAGE).symlink_to(installed / 'lib' / BOOK_PACKAGE)
    return prefix


def check_dock_watch_test(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The student's test passes on the working system and fails on each broken one."""
    test_file = package.source / TEST
    if not test_file.is_file():
        return verdict.fail(f'{package.shown(test_file)} does not exist: run '
                            "labkit.exercises.setup('ex615_dock_watch_test')")
    installed = installed_prefix(package.environment())
    if installed is None:
        return verdict.fail(f'{BOOK_PACKAGE} is not installed in the sourced workspace: '
                            f"build the book's {BOOK_PACKAGE} and source install/setup.bash")
    return grade_against_defects(
        package, verdict, test_file=test_file,
        working=f'working system ({LAUNCH_FILE} as shipped)',
        no_test_hint='whose tests wait for the system', broken=BROKEN,
        broken_prefix=partial(broken_prefix, installed))


EXERCISES = (
    Exercise('ex615_dock_watch_test', 'Exercise 6.15.1 (a launch test that catches the '
             'defects)', (TEST,), check_dock_watch_test),
)
