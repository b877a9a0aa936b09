"""Lesson 7.3 (testing and operating the capstone): every launch the lesson
starts, checked for what the lesson says about it.

- capstone.launch.py robot_count:=1 with its safety monitor killed: the
  launch log tells the story (died with -9, the handler's line, the
  capstone's reason) and `ros2 launch` exits 0;
- sim.launch.py with snippets/ch07_defects/robot_controller_unremapped.launch.py
  and the route beyond the wall: the turtle hits the wall, the safety
  monitor logs nothing after 'Guarding', the controller publishes on the
  turtle's cmd_vel beside the monitor, cmd_vel_nav has no publisher,
  stop_distance is 0.8, and `ros2 doctor` passes all its checks;
- the defect files differ from robot.launch.py only where their docstrings
  say, and the launch_pytest wall test fails on the unremapped controller,
  as the lesson claims.
(colcon test on the package, as shipped and with the monitor not critical,
is tests/snippets/test_capstone_colcon_test.py.)
"""
from __future__ import annotations

import ast
import difflib
import os
import re
import signal
import subprocess
from pathlib import Path

import labkit
from labkit.checks.ch07_03 import BrokenCapstone, broken_prefix, installed_share
from textbook import paths

from .._polling import wait_for
from ._shown_snippets import launch_files_included_by

LESSON = paths.LESSONS / 'ch07/L4/03_testing_and_operating.md'
PACKAGE = 'capstone_bringup'
ROBOT_LAUNCH = paths.SNIPPETS / PACKAGE / 'launch' / 'robot.launch.py'
DEFECTS = paths.SNIPPETS / 'ch07_defects'
UNREMAPPED = DEFECTS / 'robot_controller_unremapped.launch.py'
NOT_CRITICAL = DEFECTS / 'robot_monitor_not_critical.launch.py'
BEYOND_THE_WALL = paths.SNIPPETS / PACKAGE / 'test' / 'beyond_the_wall.yaml'
PYTEST_FILE = paths.SNIPPETS / PACKAGE / 'test' / 'test_capstone_pytest.py'
HANG_GUARD = 60.0  # seconds; only stops a broken test from hanging, never a speed limit


def _ros2(env: dict[str, str], *words: str) -> str:
    result = subprocess.run([paths.executable('ros2'), *words], env=env, capture_output=True,
                            text=True, timeout=HANG_GUARD, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout + result.stderr


def test_killing_the_safety_monitor_ends_the_capstone_with_its_reason(ros_env):
    with labkit.launch(PACKAGE, 'capstone.launch.py', robot_count=1, env=ros_env,
                       cwd=paths.WORKSPACE) as system:
        system.wait_for_output(r'\[turtle1\.mission_recorder\]: Active', HANG_GUARD)
        started = system.wait_for_output(r'\[safety_monitor-\d+\]: process started with pid',
                                         HANG_GUARD)
        os.kill(int(re.search(r'pid \[(\d+)\]', started).group(1)), signal.SIGKILL)
        wait_for(lambda: not system.running, HANG_GUARD, 'the launch to end by itself')
    story = [line for line in system.lines if re.search(
        r'process has died|exited: shutting down|Capstone shutting down', line)]
    assert system.returncode == 0, system.output()
    assert len(story) == 3, story
    assert re.search(r'\[safety_monitor-\d+\]: process has died \[pid \d+, exit code -9',
                     story[0]), story
    assert story[1].endswith('The safety monitor of turtle1 exited: shutting down'), story
    assert story[2].endswith('Capstone shutting down: the safety monitor of turtle1 exited')
    cleanly = sum('process has finished cleanly' in line for line in system.lines)
    assert cleanly == 6, system.output()  # turtlesim and the robot's five other nodes


def test_the_unremapped_controller_bypasses_the_safety_monitor(ros_env):
    with labkit.launch(PACKAGE, 'sim.launch.py', env=ros_env, cwd=paths.WORKSPACE) as sim, \
            labkit.launch(UNREMAPPED, robot_params=str(BEYOND_THE_WALL), env=ros_env,
                          cwd=paths.WORKSPACE) as robot:
        sim.wait_for_output(r'I hit the wall', HANG_GUARD)
        snapshot = labkit.graph()
        stop_distance = _ros2(ros_env, 'param', 'get', '/turtle1/safety_monitor',
                              'stop_distance')
        doctor = _ros2(ros_env, 'doctor')
        monitor_log = [line for line in robot.lines if '[turtle1.safety_monitor]' in line]
    nodes = [node for node in snapshot.nodes if node.startswith('/turtle1/')]
    assert len(nodes) == 6, snapshot.nodes
    assert sorted(snapshot.publishers('/turtle1/cmd_vel')) == [
        '/turtle1/controller', '/turtle1/safety_monitor'], str(snapshot)
    assert snapshot.publishers('/turtle1/cmd_vel_nav') == (), str(snapshot)
    assert snapshot.subscribers('/turtle1/cmd_vel_nav') == ('/turtle1/safety_monitor',)
    assert len(monitor_log) == 1 and 'Guarding: stop 0.80 m' in monitor_log[0], monitor_log
    assert 'Double value is: 0.8' in stop_distance, stop_distance
    assert re.search(r'^All \d+ checks passed$', doctor, re.M), doctor


def _code(path: Path) -> list[str]:
    """The file's lines without its module docstring."""
    tree = ast.parse(path.read_text())
    docstring_end = tree.body[0].end_lineno if ast.get_docstring(tree) else 0
    return path.read_text().splitlines()[docstring_end:]


def _changes(defect: Path) -> list[str]:
    return [line for line in difflib.unified_diff(_code(ROBOT_LAUNCH), _code(defect),
                                                  lineterm='', n=0)
            if line[:1] in '+-' and not line.startswith(('+++', '---'))]


def test_the_unremapped_controller_is_robot_launch_without_the_remap():
    assert _changes(UNREMAPPED) == [
        "-        robot_node('controller', remappings=[('cmd_vel', 'cmd_vel_nav')]),",
        "+        robot_node('controller'),  # the defect: its cmd_vel is the turtle's"]


def test_the_monitor_not_critical_is_robot_launch_without_its_exit_handler():
    removed = [line for line in _changes(NOT_CRITICAL) if line.startswith('-')]
    added = [line for line in _changes(NOT_CRITICAL) if line.startswith('+')]
    assert any('OnProcessExit(' in line for line in removed), removed
    assert not any('OnProcessExit' in line or 'Shutdown(' in line for line in added), added
    assert '-            target_action=safety_monitor,' in removed


def test_the_wall_test_fails_on_the_unremapped_controller(ros_env, tmp_path):
    share = installed_share(ros_env)
    assert share is not None
    prefix = broken_prefix(share, BrokenCapstone(
        'launch/robot.launch.py', UNREMAPPED.name, 'controller not remapped', ''), tmp_path)
    env = dict(ros_env, AMENT_PREFIX_PATH=f'{prefix}:{ros_env["AMENT_PREFIX_PATH"]}')
    result = subprocess.run(
        [paths.executable('python'), '-m', 'pytest', '-q', '-p', 'no:cacheprovider',
         str(PYTEST_FILE), '-k', 'before_the_wall'], env=env, cwd=tmp_path,
        capture_output=True, text=True, timeout=600, check=False)
    assert result.returncode == 1, result.stdout + result.stderr
    assert '1 failed, 1 deselected' in result.stdout, result.stdout
    assert 'timed out waiting for turtle1 stopped' in result.stdout, result.stdout


def test_the_lesson_shows_no_launch_file_it_does_not_test():
    assert launch_files_included_by(LESSON) == set()
