"""Lesson 6.8 (from requirements to a launch file with an assistant): the
stored draft is the assistant's reply, unchanged; the draft, the short
version and the fix launch and give the verdicts the lesson shows.

The draft must stay byte for byte the code block of the stored reply, so the
page never shows an edited draft as the assistant's.  Each launch file is
checked against the lesson's spec as the lesson checks it: the static check
through `speccheck static` in a student's terminal environment,
the running check with `speccheck.check_live` while labkit runs the launch.
Each launch gets a TMPDIR of its own, so the files it leaves behind are
counted exactly.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import labkit
import pytest
import speccheck
from textbook import paths

from ._drafts import assert_draft_is_the_replys_code_block
from ._shown_snippets import launch_files_included_by

LESSON = paths.LESSONS / 'ch06/L2/08_requirements_to_launch_file.md'
DRAFTS = paths.SNIPPETS / 'ai_drafts'
REPLY = DRAFTS / 'ch06_08_patrol' / 'response.md'
DRAFT = paths.SNIPPETS / 'my_robot_pkg' / 'launch' / 'patrol_draft.launch.py'
SPEC = paths.SNIPPETS / 'my_robot_pkg' / 'specs' / 'patrol.spec.yaml'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
NODES = ['/scout/sensor_publisher', '/scout/data_processor', '/scout/robot_controller']
#: The controller's values in config/robot_params.yaml, and its code's defaults.
FILE_VALUES = {'update_rate': 20.0, 'max_linear_speed': 0.8, 'max_angular_speed': 1.5}
CODE_DEFAULTS = {'update_rate': 10.0, 'max_linear_speed': 0.5, 'max_angular_speed': 1.0}
LEFTOVER = 'robot_controller_params_*.yaml'


def test_stored_draft_is_the_replys_code_block():
    assert_draft_is_the_replys_code_block(REPLY, DRAFT)


def test_draft_is_stored_with_its_prompt_and_note():
    folder = REPLY.parent
    assert (folder / 'prompt.md').read_text().strip(), 'the prompt is missing'
    note = (folder / 'NOTE.md').read_text()
    assert '2026-11-23' in note and 'unedited' in note, note
    assert (DRAFTS / 'COLCON_IGNORE').is_file(), 'colcon would look for packages in ai_drafts/'


def test_every_launch_file_the_lesson_shows_is_tested():
    tested = {('my_robot_pkg', name) for name in (*STATIC, *LIVE)}
    shown = launch_files_included_by(LESSON)
    assert shown, f'{LESSON.name} shows no launch file'
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'


def _static(launch_file: str, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, '-m', 'speccheck', 'static', str(SPEC), '--launch', 'my_robot_pkg',
         launch_file], env=env, capture_output=True, text=True, timeout=120, check=False)


def _lines(output: str, status: str) -> list[str]:
    return [line for line in output.splitlines() if line.startswith(f'  {status}')]


#: launch file -> (exit code, FAILED lines must mention, "not checked" lines must mention,
#: "not checked" lines must not mention)
STATIC = {
    # Everything is inside an OpaqueFunction: no node is visible, and the check says why
    # without judging them (neither met nor failed).
    'patrol_draft.launch.py': (0, [], ['OpaqueFunction',
                                       'no Node action the static check can see starts it'], []),
    # The file's key does not reach /scout/robot_controller: its values are "not set".
    'patrol_file_unchanged.launch.py': (0, [], ['update_rate', 'max_linear_speed'], []),
    # Every parameter is checked; only the topics, decided by the programs, are not.
    'patrol.launch.py': (0, [], ['/scout/cmd_vel'], ['parameter']),
}


@pytest.mark.parametrize('launch_file', list(STATIC))
def test_static_check_gives_the_lessons_verdict(launch_file: str, ros_env):
    code, failed, unchecked, checked = STATIC[launch_file]
    done = _static(launch_file, ros_env)
    report = done.stdout + done.stderr
    assert done.returncode == code, report
    failed_lines = '\n'.join(_lines(done.stdout, 'FAILED'))
    unchecked_lines = '\n'.join(_lines(done.stdout, 'not checked'))
    for phrase in failed:
        assert phrase in failed_lines, report
    for phrase in unchecked:
        assert phrase in unchecked_lines, report
    for phrase in checked:
        assert phrase not in unchecked_lines, report
    if code == 0:
        assert not failed_lines, report
    else:
        assert [line for line in _lines(done.stdout, 'met') if 'argument' in line], report


#: launch file -> (the running check passes, controller values, files the draft's code
#: left behind, launch_ros's `launch_params_*` files: one per parameter dictionary, which
#: stay after the launch, as observed on Jazzy)
LIVE = {
    'patrol_draft.launch.py': (True, FILE_VALUES, 1, 3),
    'patrol_file_unchanged.launch.py': (False, CODE_DEFAULTS, 0, 3),
    'patrol.launch.py': (True, FILE_VALUES, 0, 4),
}


@pytest.mark.parametrize('launch_file', list(LIVE))
def test_running_check_gives_the_lessons_verdict(launch_file: str, ros_env, tmp_path: Path):
    passes, controller, leftovers, dictionaries = LIVE[launch_file]
    spec = speccheck.load_spec(SPEC)
    env = {**ros_env, 'TMPDIR': str(tmp_path)}
    with labkit.launch('my_robot_pkg', launch_file, env=env, cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(NODES, timeout=HANG_GUARD)
        run.wait_for_output(r'cmd_vel linear', timeout=HANG_GUARD)  # controller wired up
        report = speccheck.check_live(spec, window=3.0)
        params = labkit.read_parameters('/scout/robot_controller')
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    assert still_running, output
    assert 'process has died' not in output, output
    assert exit_code == 0, output
    assert report.ok is passes, str(report)
    if not passes:  # what the lesson explains: exactly the file's values are missing
        failed = _lines(str(report), 'FAILED')
        assert failed and all('/scout/robot_controller: parameter' in line for line in failed), \
            str(report)
    assert {name: params.get(name) for name in controller} == controller, params
    assert params.get('robot_name') == 'scout', params
    assert len(list(tmp_path.glob(LEFTOVER))) == leftovers, sorted(tmp_path.iterdir())
    assert len(list(tmp_path.glob('launch_params_*'))) == dictionaries, sorted(tmp_path.iterdir())


#: Exercise 6.8.1's system and its planted defects: launch file -> the values its nodes get.
FRONT = {
    'front_sensor_system.launch.py': {'/front/sensor_publisher': {'publish_rate': 10.0},
                                      '/front/data_processor': {'window_size': 4}},
    'front_sensor_system_bad_rate.launch.py': {'/front/sensor_publisher': {'publish_rate': 1.0},
                                               '/front/data_processor': {'window_size': 4}},
    'front_sensor_system_bad_window.launch.py': {
        '/front/sensor_publisher': {'publish_rate': 10.0},
        '/front/data_processor': {'window_size': 5}},
}


@pytest.mark.parametrize('launch_file', list(FRONT))
def test_exercise_system_and_defects_run_with_the_values_the_check_names(launch_file: str,
                                                                         ros_env):
    """The defects are wrong values only: every node starts, runs and stops cleanly."""
    expected = FRONT[launch_file]
    with labkit.launch('my_robot_pkg', launch_file, env=ros_env, cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(list(expected), timeout=HANG_GUARD)
        got = {node: {name: labkit.read_parameters(node).get(name) for name in wanted}
               for node, wanted in expected.items()}
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    assert still_running and exit_code == 0, output
    assert 'process has died' not in output, output
    assert got == expected, output
