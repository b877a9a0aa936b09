"""The `launch_test` command: active and post-shutdown tests, their verdicts, and reports."""
from __future__ import annotations

import os
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

LAUNCH_TEST = str(Path(sys.executable).parent / 'launch_test')


def _verdicts(stderr: str) -> dict[str, str]:
    return dict(re.findall(r'^(\w+) \([\w.]+\) \.\.\. (ok|FAIL|ERROR)$', stderr, re.M))


def test_passing_file_exits_zero(run, tmp_path):
    report = tmp_path / 'report.xml'
    result = run(LAUNCH_TEST, 'lt_pass.py', '--junit-xml', str(report))
    assert result.returncode == 0, result.stdout + result.stderr
    assert _verdicts(result.stderr) == {
        'test_waits_for_output': 'ok', 'test_waits_for_stderr_by_name': 'ok',
        'test_printer_exits': 'ok', 'test_exit_codes': 'ok', 'test_in_order': 'ok'}
    assert result.stderr.count('\nOK\n') == 2  # active run, then post-shutdown run
    root = ET.parse(report).getroot()
    assert (root.get('tests'), root.get('failures'), root.get('errors')) == ('5', '0', '0')


def test_failures_and_errors_are_reported(run, tmp_path):
    report = tmp_path / 'report.xml'
    result = run(LAUNCH_TEST, 'lt_fail.py', '--junit-xml', str(report))
    assert result.returncode == 1
    assert _verdicts(result.stderr) == {
        'test_never_said': 'FAIL', 'test_silent_process': 'ERROR', 'test_raises': 'ERROR',
        'test_passes': 'ok', 'test_all_zero': 'FAIL', 'test_quitter_three': 'ok'}
    assert 'AssertionError: Waiting for output timed out' in result.stderr
    assert re.search(r'^launch_testing\.util\.proc_lookup\.NoMatchingProcessException: '
                     r'No data recorded for proc silent-2 \S+proc\.py$', result.stderr, re.M)
    assert 'AssertionError: Proc quitter-3 exited with code 3' in result.stderr
    assert 'FAILED (failures=1, errors=2)' in result.stderr
    assert 'FAILED (failures=1)' in result.stderr
    root = ET.parse(report).getroot()
    assert (root.get('tests'), root.get('failures'), root.get('errors')) == ('6', '2', '2')


def test_ready_timeout_stops_the_launch_without_running_tests(run):
    result = run(LAUNCH_TEST, 'lt_ready_timeout.py')
    assert result.returncode == 1
    messages = [line for line in result.stdout.splitlines() if not line.startswith('[')]
    assert messages == [
        'Timed out waiting for processes to start up',
        'Processes under test stopped before tests completed']
    assert 'must not run' not in result.stderr
    assert 'Ran ' not in result.stderr


def test_parametrize_runs_the_file_once_per_value(run):
    result = run(LAUNCH_TEST, 'lt_params.py', 'greeting:=howdy')
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stderr.count('test_says_word (lt_params.TestSpeaker.test_says_word) ... ok') \
        == 2


def test_launch_arguments_reach_the_description(run):
    result = run(LAUNCH_TEST, 'lt_params.py')  # default greeting 'hi', never 'howdy'
    assert result.returncode == 1
    assert 'AssertionError: Waiting for output timed out' in result.stderr


def test_show_args_lists_declared_arguments(run):
    result = run(LAUNCH_TEST, 'lt_params.py', '--show-args')
    assert result.returncode == 0
    assert "    'greeting':" in result.stdout
    assert 'What the speaker says' in result.stdout
    assert 'Ran ' not in result.stderr


def test_missing_file_is_a_clear_error(run):
    result = run(LAUNCH_TEST, 'no_such_test.py')
    assert result.returncode == 2
    assert "no_such_test.py' does not exist" in result.stderr


def test_malformed_launch_argument_is_a_clear_error(run):
    result = run(LAUNCH_TEST, 'lt_pass.py', 'greeting=howdy')
    assert result.returncode == 2
    assert "malformed launch argument 'greeting=howdy'" in result.stderr


def test_bad_description_is_a_clear_error(run):
    result = run(LAUNCH_TEST, 'lt_bad_return.py')
    assert result.returncode == 2
    assert "generate_test_description() of '" in result.stderr
    assert "lt_bad_return.py' must return a LaunchDescription or a (LaunchDescription, dict) " \
        'tuple, not list' in result.stderr


def test_a_run_gets_its_own_domain_when_none_is_set(run_env):
    from launch_testing.domain_isolation import isolated_domain

    saved = os.environ.pop('ROS_DOMAIN_ID', None)
    try:
        with isolated_domain() as first, isolated_domain() as nested:
            assert first is not None and 1 <= first <= 89
            assert os.environ['ROS_DOMAIN_ID'] == str(first)
            assert nested is None  # already isolated: kept as is
        assert 'ROS_DOMAIN_ID' not in os.environ
    finally:
        if saved is not None:
            os.environ['ROS_DOMAIN_ID'] = saved


def test_a_process_name_nothing_matches_names_the_processes_there_are(run):
    # Observed on the reference (launch_testing 3.4.3): sorted 'name-N args' of each.
    result = run(LAUNCH_TEST, 'lt_proc_lookup.py')
    assert result.returncode == 1
    assert ("launch_testing.util.proc_lookup.NoMatchingProcessException: Did not find any "
            "processes matching name 'dock' and args 'None'. Procs: listener-2 31, talker-1 30"
            in result.stderr.splitlines()), result.stderr
