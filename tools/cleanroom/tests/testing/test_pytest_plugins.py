"""pytest with our plugins: launch_pytest tests and launch_testing files collected by pytest."""
from __future__ import annotations

import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from launch_testing.pytest.hooks import is_launch_test_file

PYTEST = [sys.executable, '-m', 'pytest', '-rA', '-p', 'no:cacheprovider', '-p', 'no:xdist',
          '-p', 'no:randomly']


def _outcomes(stdout: str) -> dict[str, str]:
    return {name: outcome for outcome, name in
            re.findall(r'^(PASSED|FAILED|ERROR) \S+::(\w+)', stdout, re.M)}


def test_launch_pytest_tests(run):
    result = run(*PYTEST, '-v', '-o', 'python_files=lp_*.py', 'lp_cases.py')
    assert result.returncode == 1, result.stdout
    assert _outcomes(result.stdout) == {
        'test_async_tools': 'PASSED', 'test_sync_tools': 'PASSED', 'test_generator': 'PASSED',
        'test_after_shutdown': 'PASSED', 'test_output_never_comes': 'FAILED',
        'test_errors': 'FAILED', 'test_times_out': 'FAILED',
        'test_plain_test_is_left_alone': 'PASSED'}, result.stdout
    assert 'FAILED lp_cases.py::test_output_never_comes - assert False' in result.stdout
    assert 'RuntimeError: broken test' in result.stdout
    assert 'Timeout' in result.stdout
    # shutdown tests run after the others of their module (-v names each test as it starts;
    # the launch, running in its own thread, may print its lines right after the name)
    order = re.findall(r'^\S+::(\w+)', result.stdout, re.M)
    assert order.index('test_after_shutdown') > order.index('test_times_out')


def test_a_yielding_test_of_a_module_launch_is_two_items(run):
    """As Jazzy: the part before yield runs in place, the part after it among the
    shutdown tests (in the order of the file), skipped when the first part failed."""
    result = run(*PYTEST, '-v', '-o', 'python_files=lp_*.py', 'lp_split.py')
    assert result.returncode == 1, result.stdout
    # (the launch, in its own thread, may print a line right after a test's name)
    shown = re.sub(r'\[(?:INFO|ERROR)\] \[[\w.-]+\]: [^\n]*\n', '', result.stdout)
    ran = re.findall(r'^lp_split\.py::(\w+) .*?(PASSED|FAILED|SKIPPED)', shown, re.M)
    assert ran == [('test_b_both_parts_pass', 'PASSED'), ('test_c_fails_before', 'FAILED'),
                   ('test_d_fails_after', 'PASSED'), ('test_e_plain', 'PASSED'),
                   ('test_a_shutdown', 'PASSED'), ('test_b_both_parts_pass', 'PASSED'),
                   ('test_c_fails_before', 'SKIPPED'), ('test_d_fails_after', 'FAILED')], \
        result.stdout
    assert 'shutdown test skipped because the test failed before' in result.stdout
    assert '2 failed, 5 passed, 1 skipped' in result.stdout


def test_launch_testing_file_collected_by_pytest(run, tmp_path):
    report = tmp_path / 'pytest.xml'
    result = run(*PYTEST, '-o', 'python_files=lt_*.py', f'--junit-xml={report}',
                 'lt_pass.py', 'lt_fail.py')
    assert result.returncode == 1, result.stdout
    assert _outcomes(result.stdout) == {'lt_pass': 'PASSED', 'lt_fail': 'FAILED'}
    assert 'FAIL: lt_fail.TestActive.test_never_said: AssertionError: Waiting for output ' \
        'timed out' in result.stdout
    suite = ET.parse(report).getroot().find('testsuite')
    assert (suite.get('tests'), suite.get('failures')) == ('2', '1')


def test_timed_out_launch_test_leaves_no_process(run):
    """pytest-timeout interrupts the run; its whole process group is stopped."""
    result = run(*PYTEST, '-o', 'python_files=lt_*.py', '-o', 'timeout=8', 'lt_slow.py')
    assert result.returncode == 1, result.stdout
    assert _outcomes(result.stdout) == {'lt_slow': 'FAILED'}
    assert 'Timeout (>8.0s)' in result.stdout
    # the run_env fixture fails this test if the launch or its sleeper survived


def test_only_launch_testing_files_are_taken(tmp_path):
    launch_testing_file = tmp_path / 'test_a.py'
    launch_testing_file.write_text('def generate_test_description():\n    pass\n')
    launch_pytest_file = tmp_path / 'test_b.py'
    launch_pytest_file.write_text(
        'import launch_pytest\n\n@launch_pytest.fixture\n'
        'def generate_test_description():\n    pass\n')
    ordinary = tmp_path / 'test_c.py'
    ordinary.write_text('def test_x():\n    generate_test_description = 1\n')
    broken = tmp_path / 'test_d.py'
    broken.write_text('def generate_test_description(:\n')
    assert is_launch_test_file(launch_testing_file)
    assert not is_launch_test_file(launch_pytest_file)
    assert not is_launch_test_file(ordinary)
    assert not is_launch_test_file(broken)
    assert not is_launch_test_file(Path(__file__))


def test_the_launchs_first_lines_belong_to_the_fixtures_setup(run):
    """As Jazzy: the launch has logged where its logs go and its verbosity before the
    fixture's setup ends, so no line of it leaks between pytest's phases (with -q a
    leaked line stood above the dots)."""
    result = run(*PYTEST, '-q', '--color=no', '-o', 'python_files=lp_*.py', 'lp_setup_lines.py')
    assert result.returncode == 0, result.stdout
    setup = result.stdout.split('Captured stdout setup')[1].split('Captured stdout call')[0]
    assert '[INFO] [launch]: All log files can be found below' in setup, result.stdout
    assert '[INFO] [launch]: Default logging verbosity is set to INFO' in setup, result.stdout
    assert not result.stdout.startswith('['), result.stdout
