"""Lesson 6.15 (integration tests for launch files): dock_watch_pkg's tests run
as a student runs them, and fail for the reasons the lesson gives.

`colcon test` and `colcon test-result --verbose` in a scratch workspace
holding a copy of the package: clean on the package as shipped, and failing,
naming exactly the static spec test (the only test that reads the launch
file's defaults; the launch_pytest tests start the nodes themselves), once
the rate of requirement R2 is planted back to 2.0 in the copy's launch file
(the lesson's planted defect).  Then
`launch_test` on the test file, and the pitfalls the lesson shows live: a
test that never waits passes on a broken system; a test that only listens to
/battery_low passes on a broken system while a working copy runs in the same
domain, and fails without it; a check that reads the output once passes
after a test that waited.  Every run is marked in its environment, and
none of its processes may outlive it.
"""
from __future__ import annotations

import re
import subprocess
from collections.abc import Iterator
from pathlib import Path

import labkit
import pytest
from textbook import paths

from ._colcon_runs import build_copy, colcon_test, marked_environment, run

PACKAGE = 'dock_watch_pkg'
SOURCE = paths.SNIPPETS / PACKAGE
TESTS = SOURCE / 'test'
HANG_GUARD = 600  # seconds; only stops a hung run, never a speed limit
MARK = 'LESSON_615_RUN'
ALL_TESTS = {'test_dock_watch_launch', 'test_chain_connected', 'test_running_system_meets_spec',
             'test_planner_ends_cleanly', 'test_launch_file_meets_spec_statically'}
SPEC_TESTS = {'test_launch_file_meets_spec_statically'}  # the only one reading the file
RATE_LINE = "DeclareLaunchArgument('battery_rate', default_value='5.0',"
PLANTED_RATE = "DeclareLaunchArgument('battery_rate', default_value='2.0',"


@pytest.fixture
def run_env(ros_env: dict[str, str]) -> Iterator[dict[str, str]]:
    """The student's terminal, marked; fails the test if a marked process survives it."""
    yield from marked_environment(ros_env, MARK)


def _run(argv: list[str], env: dict[str, str], cwd: Path) -> subprocess.CompletedProcess[str]:
    return run(argv, env, cwd, HANG_GUARD)


def _plant_rate(package: Path) -> None:
    launch_file = package / 'launch' / 'dock_watch_v2.launch.py'
    text = launch_file.read_text()
    assert RATE_LINE in text, 'the lesson plants its defect in this line'
    launch_file.write_text(text.replace(RATE_LINE, PLANTED_RATE))


def _workspace(root: Path, env: dict[str, str], planted: bool = False) -> dict[str, str]:
    """A workspace with a copy of the package (the rate planted back to 2.0 if asked), built."""
    return build_copy(root, PACKAGE, env, HANG_GUARD, edit=_plant_rate if planted else None)


def _colcon_test(root: Path, env: dict[str, str]) -> tuple[subprocess.CompletedProcess[str],
                                                           dict[str, str]]:
    return colcon_test(root, PACKAGE, env, HANG_GUARD)


def test_colcon_test_passes_on_the_package(tmp_path, run_env):
    env = _workspace(tmp_path, run_env)
    result, outcomes = _colcon_test(tmp_path, env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert outcomes == dict.fromkeys(ALL_TESTS, 'passed'), outcomes
    assert re.search(r'Summary: 6 tests, 0 errors, 0 failures, 0 skipped', result.stdout), \
        result.stdout


def test_colcon_test_names_the_spec_tests_on_the_planted_rate(tmp_path, run_env):
    env = _workspace(tmp_path, run_env, planted=True)
    result, outcomes = _colcon_test(tmp_path, env)
    assert result.returncode != 0, result.stdout
    assert {name for name, outcome in outcomes.items() if outcome == 'failed'} == SPEC_TESTS, \
        outcomes
    assert set(outcomes) == ALL_TESTS
    assert 'Summary: 6 tests, 0 errors, 1 failure, 0 skipped' in result.stdout, result.stdout
    # the report a student reads names the argument and the parameter of R2
    assert "argument battery_rate: default '2.0', the spec says '5.0'" in result.stdout


def _verdicts(stderr: str) -> dict[str, str]:
    return dict(re.findall(r'^(\w+) \([\w.]+\) \.\.\. (ok|FAIL|ERROR)$', stderr, re.M))


def test_launch_test_runs_the_active_then_the_post_shutdown_tests(run_env):
    result = _run([paths.executable('launch_test'), str(TESTS / 'test_dock_watch_launch.py')],
                  run_env, paths.WORKSPACE)
    assert result.returncode == 0, result.stdout + result.stderr
    assert _verdicts(result.stderr) == {
        'test_chain_connected': 'ok', 'test_topics_carry_messages': 'ok',
        'test_goes_to_the_dock': 'ok', 'test_exit_codes': 'ok'}, result.stderr
    assert re.findall(r'^Ran (\d+) tests? in', result.stderr, re.M) == ['3', '1']


def _pitfall(name: str, defect: str, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return _run([paths.executable('launch_test'), str(TESTS / 'pitfalls' / name),
                 f'system:={TESTS / "defects" / defect}'], env, paths.WORKSPACE)


def test_a_test_that_never_waits_passes_on_a_deaf_monitor(run_env):
    result = _pitfall('never_waits.py', 'deaf_monitor.launch.py', run_env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert _verdicts(result.stderr) == {'test_no_errors_logged': 'ok'}


def test_a_topic_check_hears_another_system_in_the_same_domain(run_env):
    with labkit.launch(PACKAGE, 'dock_watch_v2.launch.py', env=run_env) as working:
        working.wait_for_output(r'First report')
        crossed = _pitfall('topic_only.py', 'deaf_monitor.launch.py', run_env)
    assert crossed.returncode == 0, crossed.stdout + crossed.stderr
    alone = _pitfall('topic_only.py', 'deaf_monitor.launch.py', run_env)
    assert alone.returncode == 1, alone.stdout + alone.stderr
    assert _verdicts(alone.stderr) == {'test_battery_low_published': 'ERROR'}
    assert "RuntimeError: ('Did not receive messages on these topics: ', {'battery_low'})" \
        in alone.stderr


def test_reading_the_output_once_passes_only_after_a_test_that_waited(run_env):
    """test_c is test_a's check, run after test_b waited for the line: it must pass.
    (test_a's own result depends on timing, which is the lesson's point, so it is
    not asserted here.)"""
    result = _run([paths.executable('launch_test'), str(TESTS / 'pitfalls' / 'reads_once.py'),
                   f'system:={SOURCE / "launch" / "dock_watch_v2.launch.py"}'],
                  run_env, paths.WORKSPACE)
    verdicts = _verdicts(result.stderr)
    assert set(verdicts) == {'test_a_reads_once', 'test_b_waits', 'test_c_reads_once'}, \
        result.stderr
    assert (verdicts['test_b_waits'], verdicts['test_c_reads_once']) == ('ok', 'ok'), \
        result.stderr
