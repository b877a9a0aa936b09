"""Launch files of lesson 6.6 (events and processes) produce the processes and
the events the lesson explains.

Each launch file is started as the lesson starts it (``ros2 launch PKG FILE``,
through labkit).  The tests wait for states (a log line, nodes in the graph,
the launch ending by itself), never for a fixed time, and then hold the
launch output to what the lesson says: which processes started, in which
order one event led to the next (a handler's LogInfo after the event it
reacts to, the processor after the sensor, a respawn after the death), and
how Ctrl+C escalates to SIGTERM and SIGKILL for nodes that do not stop.
Order is asserted only where one line causes the next.
"""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import labkit
import pytest
from labkit import checks
from labkit.background import Background
from textbook import paths

from .._polling import poll
from ._shown_snippets import launch_files_included_by

LESSON = paths.LESSONS / 'ch06/L1/06_events_and_processes.md'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
PACKAGE = 'my_robot_pkg'


def _start(launch_file: str, ros_env: dict[str, str]) -> Background:
    return labkit.launch(PACKAGE, launch_file, env=ros_env, cwd=paths.WORKSPACE)


def _wait_for_exit(run: Background) -> int:
    """Wait until the launch ends by itself (fails, after the hang guard, if it does not)."""
    ended_by_itself = poll(lambda: not run.running, HANG_GUARD)
    code = run.stop()
    assert ended_by_itself, f'the launch did not end by itself:\n{run.output()}'
    return code


def _index(lines: list[str], pattern: str, start: int = 0) -> int:
    """Index of the first line at or after `start` matching the regex `pattern`."""
    regex = re.compile(pattern)
    for number, line in enumerate(lines[start:], start):
        if regex.search(line):
            return number
    raise AssertionError(f'no line matching {pattern!r} after line {start}:\n'
                         + '\n'.join(lines))


def _in_order(lines: list[str], *patterns: str) -> list[int]:
    """Each pattern matches a line after the previous one's; returns their indexes."""
    found, start = [], 0
    for pattern in patterns:
        start = _index(lines, pattern, start) + 1
        found.append(start - 1)
    return found


def _wait_for_count(run: Background, pattern: str, count: int) -> None:
    """Wait until `count` lines match `pattern` (or the launch ends, or the hang guard)."""
    poll(lambda: _count(run.lines, pattern) >= count, HANG_GUARD, stop=lambda: not run.running)


def _count(lines: list[str], pattern: str) -> int:
    return sum(bool(re.search(pattern, line)) for line in lines)


def test_commands_run_with_their_folder_environment_and_handlers(ros_env):
    run = _start('process_commands.launch.py', ros_env)
    code = _wait_for_exit(run)
    lines = run.lines
    uname = subprocess.run(['uname', '-s', '-m'], capture_output=True, text=True,
                           check=True).stdout.strip()
    assert code == 0, run.output()
    assert f'[system_info-1] {uname}' in lines, run.output()
    # shell=True expanded $ROBOT_NAME (additional_env) and $(pwd) (cwd)
    assert '[greeter-2] robot alpha works in /tmp' in lines, run.output()
    # OnProcessIO turned the greeter's stdout into a LogInfo line; as in Jazzy, the
    # launch file's handler (the newest) runs before the one that prints the line
    _in_order(lines, r'^\[INFO\] \[launch\.user\]: greeter said: robot alpha works in /tmp$',
              r'^\[greeter-2\] robot alpha')
    # OnProcessExit without a target: one line per process, after its exit
    for process in ('system_info-1', 'greeter-2'):
        _in_order(lines, rf'^\[INFO\] \[{process}\]: process has finished cleanly',
                  rf'^\[INFO\] \[launch\.user\]: {process} exited with code 0$')
    assert _count(lines, r'exited with code') == 2, run.output()


def test_set_environment_variable_reaches_later_processes_and_ends_with_its_group(ros_env):
    run = labkit.launch(PACKAGE, 'process_environment.launch.py', env=dict(
        ros_env, ROBOT_NAME='alpha'), cwd=paths.WORKSPACE)
    code = _wait_for_exit(run)
    assert code == 0, run.output()
    shown = sorted((line for line in run.lines if ' ROBOT_NAME=' in line),
                   key=lambda line: int(line.split('-')[1].split(']')[0]))
    # the terminal's value before the action, the group's inside it, the action's after
    assert shown == ['[before-1] ROBOT_NAME=alpha', '[in_group-2] ROBOT_NAME=gamma',
                     '[after_group-3] ROBOT_NAME=beta'], run.output()


def test_execution_complete_fires_only_for_a_handler_registered_before_its_action(ros_env):
    run = _start('events_execution_complete.launch.py', ros_env)
    code = _wait_for_exit(run)
    assert code == 0, run.output()
    _in_order(run.lines, r'^\[INFO\] \[calibrate-1\]: process has finished cleanly',
              r'^\[INFO\] \[launch\.user\]: calibrate complete$')
    assert _count(run.lines, r'\[launch\.user\]: timer: one second$') == 1, run.output()
    assert _count(run.lines, r'announce complete') == 0, run.output()


def test_without_a_shell_the_shell_syntax_is_printed_as_it_is(ros_env):
    run = _start('process_no_shell.launch.py', ros_env)
    code = _wait_for_exit(run)
    assert code == 0, run.output()
    assert '[greeter-1] robot $ROBOT_NAME works in $(pwd)' in run.lines, run.output()


def test_find_executable_of_a_missing_program_ends_the_launch(ros_env):
    run = _start('process_missing_executable.launch.py', ros_env)
    code = _wait_for_exit(run)
    assert code == 1, run.output()
    assert any(re.fullmatch(
        r"\[ERROR\] \[launch\]: Caught exception in launch \(see debug for traceback\): "
        r"executable '\[<launch\.substitutions\.text_substitution\.TextSubstitution object at "
        r"0x[0-9a-f]+>\]' not found on the PATH", line) for line in run.lines), run.output()
    assert _count(run.lines, r'process started') == 0, run.output()


def test_timer_starts_the_processor_after_the_sensor(ros_env):
    with _start('events_timer.launch.py', ros_env) as run:
        run.wait_for_nodes(['/flaky_sensor', '/data_processor'], timeout=HANG_GUARD)
        run.wait_for_output(r'\[data_processor\]: Received', timeout=HANG_GUARD)
        code = run.stop()
    lines = run.lines
    _in_order(lines, r'^\[INFO\] \[flaky_sensor-1\]: process started',
              r'^\[INFO\] \[data_processor-2\]: process started')
    assert code == 0 and 'process has died' not in run.output(), run.output()


def test_on_process_start_starts_the_processor_once_the_sensor_process_runs(ros_env):
    with _start('events_on_start.launch.py', ros_env) as run:
        run.wait_for_nodes(['/flaky_sensor', '/data_processor'], timeout=HANG_GUARD)
        run.wait_for_output(r'\[data_processor\]: Received', timeout=HANG_GUARD)
        code = run.stop()
    lines = run.lines
    _in_order(lines, r'^\[INFO\] \[flaky_sensor-1\]: process started',
              r'^\[INFO\] \[launch\.user\]: The sensor process has started: starting the '
              r'processor$',
              r'^\[INFO\] \[data_processor-2\]: process started')
    assert code == 0 and 'process has died' not in run.output(), run.output()


def test_the_launch_shuts_down_when_the_critical_sensor_dies(ros_env):
    run = _start('events_critical.launch.py', ros_env)
    code = _wait_for_exit(run)
    lines = run.lines
    assert code == 0, run.output()
    # the launch file's OnProcessIO runs before the handler that prints the line (Jazzy)
    _in_order(lines, r'^\[INFO\] \[launch\.user\]: The sensor reported a hardware fault$',
              r'\[flaky_sensor\]: Lost contact with the sensor hardware')
    _in_order(lines, r'\[flaky_sensor\]: Reading #4:',
              r'^\[ERROR\] \[flaky_sensor-1\]: process has died \[pid \d+, exit code 1, ',
              r'^\[INFO\] \[launch\.user\]: The sensor is gone: nothing works without it',
              r'^\[INFO\] \[launch\.user\]: Launch is shutting down: the sensor died$',
              r"^\[INFO\] \[data_processor-2\]: sending signal 'SIGINT' to "
              r"process\[data_processor-2\]$",
              r'^\[INFO\] \[data_processor-2\]: process has finished cleanly')
    assert _count(lines, r'\[flaky_sensor\]: Reading #') == 4, run.output()
    assert _count(lines, r'process started') == 2, run.output()


def test_respawn_starts_the_dead_sensor_again(ros_env):
    started = r'^\[INFO\] \[flaky_sensor-1\]: process started with pid \[(\d+)\]'
    with _start('events_respawn.launch.py', ros_env) as run:
        run.wait_for_nodes(['/flaky_sensor', '/data_processor'], timeout=HANG_GUARD)
        run.wait_for_output(r'process has died', timeout=HANG_GUARD)
        _wait_for_count(run, r'\[flaky_sensor\]: Calibrating', 2)  # the new process logs
        lines = run.lines
        first, died, second = _in_order(
            lines, started, r'^\[ERROR\] \[flaky_sensor-1\]: process has died \[pid \d+, '
            r'exit code 1, ', started)
        _index(lines, r'\[flaky_sensor\]: Calibrating', second)  # the new process runs
        still_running = run.running
        run.stop()
    pids = [re.match(started, lines[i]).group(1) for i in (first, second)]
    assert pids[0] != pids[1], run.output()
    assert still_running, run.output()
    # the processor was never restarted: it kept running through the sensor's death
    assert _count(run.lines, r'^\[INFO\] \[data_processor-2\]: process started') == 1
    assert _count(run.lines, r'data_processor-\d+\]: process has (died|finished)') == 1


def test_ctrl_c_escalates_to_sigterm_and_sigkill(ros_env):
    with _start('process_stubborn.launch.py', ros_env) as run:
        run.wait_for_nodes(['/sensor_publisher', '/map_saver', '/hung_driver'],
                           timeout=HANG_GUARD)
        for node in ('map_saver', 'hung_driver'):  # logged once its signal handlers are set
            run.wait_for_output(rf'\[{node}\]: Saving the map', timeout=HANG_GUARD)
        run.stop()
    lines = run.lines
    interrupted = _index(lines, r'^\[WARNING\] \[launch\]: user interrupted with ctrl-c '
                                r'\(SIGINT\)$')
    _index(lines, r'^\[INFO\] \[sensor_publisher-1\]: process has finished cleanly', interrupted)
    # map_saver (stubborn_node-2) ignores SIGINT and stops on SIGTERM
    _in_order(lines[interrupted:],
              r'\[map_saver\]: Got SIGINT: ignoring it',
              r"^\[ERROR\] \[stubborn_node-2\]: process\[stubborn_node-2\] failed to terminate "
              r"'2' seconds after receiving 'SIGINT', escalating to 'SIGTERM'$",
              r"^\[INFO\] \[stubborn_node-2\]: sending signal 'SIGTERM' to "
              r"process\[stubborn_node-2\]$",
              r'\[map_saver\]: Got SIGTERM: stopping',
              r'^\[INFO\] \[stubborn_node-2\]: process has finished cleanly')
    # hung_driver (stubborn_node-3) ignores both and is killed
    _in_order(lines[interrupted:],
              r'\[hung_driver\]: Got SIGINT: ignoring it',
              r"^\[INFO\] \[stubborn_node-3\]: sending signal 'SIGTERM' to "
              r"process\[stubborn_node-3\]$",
              r'\[hung_driver\]: Got SIGTERM: ignoring it too',
              r"^\[ERROR\] \[stubborn_node-3\]: process\[stubborn_node-3\] failed to terminate "
              r"'4.0' seconds after receiving 'SIGTERM', escalating to 'SIGKILL'$",
              r"^\[INFO\] \[stubborn_node-3\]: sending signal 'SIGKILL' to "
              r"process\[stubborn_node-3\]$",
              r'^\[ERROR\] \[stubborn_node-3\]: process has died \[pid \d+, exit code -9, ')
    # the node that stops on Ctrl+C got no escalation
    assert _count(lines, r'sensor_publisher-1\]: (process\[|sending signal)') == 0, run.output()


def _graded_by_exercise_checks() -> set[tuple[str, str]]:
    """Exercise solutions of this lesson: tests/exercises launches them as a
    student's package and holds them to their check."""
    return {('ch06_solutions', Path(relative).name)
            for exercise in checks.EXERCISES.values() if exercise.id.startswith('ex66_')
            for relative in exercise.files if relative.startswith('launch/')}


TESTED = {(PACKAGE, name) for name in (
    'process_commands.launch.py', 'process_environment.launch.py', 'process_no_shell.launch.py',
    'process_missing_executable.launch.py', 'events_timer.launch.py',
    'events_execution_complete.launch.py',
    'events_on_start.launch.py', 'events_critical.launch.py', 'events_respawn.launch.py',
    'process_stubborn.launch.py')}


def test_every_launch_file_the_lesson_shows_is_tested():
    shown = launch_files_included_by(LESSON)
    assert shown, f'{LESSON.name} shows no launch file'
    tested = TESTED | _graded_by_exercise_checks()
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'


@pytest.mark.parametrize('pattern', ['events_*.launch.py', 'process_*.launch.py'])
def test_every_new_snippet_of_the_lesson_is_tested(pattern):
    files = {(PACKAGE, p.name) for p in (paths.SNIPPETS / PACKAGE / 'launch').glob(pattern)}
    assert files and files <= TESTED, sorted(files - TESTED)


def test_every_exercise_solution_of_the_lesson_is_graded():
    files = {('ch06_solutions', p.name)
             for p in (paths.SNIPPETS / 'ch06_solutions' / 'launch').glob('ex66_*.launch.py')}
    assert files and files <= _graded_by_exercise_checks(), sorted(files)
