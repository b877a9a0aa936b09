"""The capstone's own integration tests (capstone_bringup/test/, lesson 7.3) run
under `colcon test` as CI and a student run them, and can fail.

On the package as shipped, every test passes: lesson 7.3 runs exactly that
`colcon test` and prints its summary, so the executed lesson (shared with
tests/lessons through the lesson cache) is the evidence, not a second run.
A scratch workspace holds a copy of capstone_bringup (its dependencies come
from the book's workspace underneath), built and tested with `colcon test
--packages-select capstone_bringup`, then read with `colcon test-result
--verbose` and the package's pytest.xml: with
snippets/ch07_defects/robot_monitor_not_critical.launch.py planted as the
copy's robot.launch.py (the safety monitor's exit no longer shuts the launch
down), exactly the launch_testing test fails, and its
report says what did not happen.  Every run is marked in its environment,
and none of its processes may outlive it.
"""
from __future__ import annotations

import shutil
import subprocess
from collections.abc import Iterator
from functools import partial
from pathlib import Path

import pytest
from textbook import execute, paths
from textbook.lessons import load

from ._colcon_runs import build_copy, colcon_test, marked_environment

PACKAGE = 'capstone_bringup'
LESSON = paths.ROOT / 'lessons' / 'ch07' / 'L4' / '03_testing_and_operating.md'
NOT_CRITICAL = paths.SNIPPETS / 'ch07_defects' / 'robot_monitor_not_critical.launch.py'
HANG_GUARD = 900  # seconds; only stops a hung run, never a speed limit
MARK = 'CAPSTONE_COLCON_TEST_RUN'
LAUNCH_TESTING = 'test_capstone_launch'  # launch_testing reports a file as one test
PYTEST_TESTS = {'test_safety_monitor_stops_the_turtle_before_the_wall',
                'test_killed_wall_sensor_comes_back_while_the_robot_holds_still'}


@pytest.fixture
def run_env(ros_env: dict[str, str]) -> Iterator[dict[str, str]]:
    """The student's terminal, marked; fails the test if a marked process survives it."""
    yield from marked_environment(ros_env, MARK)


def _plant(robot_launch: Path, package: Path) -> None:
    shutil.copyfile(robot_launch, package / 'launch' / 'robot.launch.py')


def _workspace(root: Path, env: dict[str, str], robot_launch: Path | None = None
               ) -> dict[str, str]:
    """A workspace with a copy of the package (robot.launch.py replaced if asked), built."""
    return build_copy(root, PACKAGE, env, HANG_GUARD,
                      edit=partial(_plant, robot_launch) if robot_launch else None)


def _colcon_test(root: Path, env: dict[str, str]) -> tuple[subprocess.CompletedProcess[str],
                                                           dict[str, str]]:
    return colcon_test(root, PACKAGE, env, HANG_GUARD)


def _hangs(root: Path) -> str:
    """The launch log's 'failed to terminate' lines of the last colcon test, if any: a
    node that ignored its SIGINT (the Fast DDS hang tools/ddsfix prevents), named."""
    log = root / 'log' / 'latest_test' / PACKAGE / 'stdout_stderr.log'
    lines = log.read_text(errors='replace').splitlines() if log.is_file() else []
    return '\n'.join(line for line in lines if 'failed to terminate' in line)


def test_colcon_test_passes_on_the_capstone():
    """Lesson 7.3's `colcon test` cell, as executed: all three tests passed, exit code 0."""
    cells = [cell for cell in execute.executed(load(LESSON)).cells
             if cell.cell_type == 'code' and 'colcon test --packages-select' in cell.source]
    assert len(cells) == 1, f'lesson 7.3 should run colcon test once, not {len(cells)} times'
    shown = ''.join(output.get('text', '') for output in cells[0].outputs)
    assert shown == 'Summary: 3 tests, 0 errors, 0 failures, 0 skipped\nexit code: 0\n', shown


def test_colcon_test_fails_when_the_safety_monitor_is_not_critical(tmp_path, run_env):
    env = _workspace(tmp_path, run_env, robot_launch=NOT_CRITICAL)
    result, outcomes = _colcon_test(tmp_path, env)
    assert result.returncode != 0, result.stdout
    assert outcomes == {**dict.fromkeys(PYTEST_TESTS, 'passed'), LAUNCH_TESTING: 'failed'}, \
        (outcomes, result.stdout, _hangs(tmp_path))
    assert 'Summary: 3 tests, 0 errors, 1 failure, 0 skipped' in result.stdout, result.stdout
    # the report a student reads names the active test that waited in vain ...
    assert 'test_4_fault_safety_monitor_killed' in result.stdout, result.stdout
    assert 'the launch did not shut down' in result.stdout, result.stdout
