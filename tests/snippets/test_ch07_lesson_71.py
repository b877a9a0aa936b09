"""Lesson 7.1 (the capstone's specification): capstone_bringup installs the
capstone's spec, the launch the lesson runs meets it while running, and the
static check gives the lesson's verdict: it sees the arguments and
turtlesim, and none of the robots' nodes, which an OpaqueFunction makes.

Expected names come from the spec itself (`speccheck.load_spec`), so the
spec and the system can only change together.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import labkit
import speccheck
from textbook import paths

from ._shown_snippets import launch_files_included_by

LESSON = paths.LESSONS / 'ch07/L4/01_specification.md'
PACKAGE = 'capstone_bringup'
LAUNCH = 'capstone.launch.py'
SPEC = paths.SNIPPETS / PACKAGE / 'specs' / 'capstone.spec.yaml'
HANG_GUARD = 60.0  # seconds; only stops a broken test from hanging, never a speed limit
ROBOTS = ('turtle1', 'turtle2')
#: exercise 7.1.1: the solution's spec and the planted defect its check runs it against
EXERCISE_SPEC = paths.SNIPPETS / 'ch06_solutions' / 'specs' / 'ex71_third_robot.spec.yaml'
DEFECT = paths.SNIPPETS / 'ch07_defects' / 'turtle3_other_config.launch.py'


def _installed_spec(env: dict[str, str]) -> Path | None:
    for prefix in filter(None, env.get('AMENT_PREFIX_PATH', '').split(':')):
        candidate = Path(prefix) / 'share' / PACKAGE / 'specs' / SPEC.name
        if candidate.is_file():
            return candidate
    return None


def test_the_spec_is_installed_with_the_bringup_package(ros_env):
    installed = _installed_spec(ros_env)
    assert installed is not None, f'{SPEC.name} is not in share/{PACKAGE}/specs'
    assert installed.read_text() == SPEC.read_text()


def test_every_spec_entry_names_its_requirement():
    """Requirement traceability: each node, topic and argument line says R<n>."""
    spec = speccheck.load_spec(SPEC)
    lines = SPEC.read_text().splitlines()
    names = [node.name for node in spec.nodes] + [topic.name for topic in spec.topics]
    for name in names:
        line = next(line for line in lines if line.strip().startswith(f'{name}:'))
        assert '# R' in line, f'{name} names no requirement: {line!r}'
    assert any(line.startswith('arguments:') and '# R8' in line for line in lines)


def test_static_check_sees_the_arguments_and_turtlesim_but_no_robot(ros_env):
    spec = speccheck.load_spec(SPEC)
    done = subprocess.run(
        [sys.executable, '-m', 'speccheck', 'static', str(SPEC), '--launch', PACKAGE, LAUNCH],
        env=ros_env, capture_output=True, text=True, timeout=120, check=False)
    report = done.stdout + done.stderr
    assert done.returncode == 0, report  # nothing failed: what it cannot see is not judged
    met = [line.strip() for line in done.stdout.splitlines() if line.startswith('  met')]
    for expected in ("argument sim: declared, default 'true'",
                     "argument robot_count: declared, default '2'",
                     'node /turtlesim: started by sim.launch.py as turtlesim/turtlesim_node'):
        assert any(expected in line for line in met), f'{expected!r} not met in\n{report}'
    unseen = [line for line in done.stdout.splitlines()
              if line.startswith('  not checked node ')
              and 'no Node action the static check can see starts it' in line]
    robot_nodes = [node.name for node in spec.nodes if node.name != '/turtlesim']
    assert len(unseen) == len(robot_nodes) == 12, report
    assert all(any(f'node {name}:' in line for line in unseen) for name in robot_nodes), report
    assert 'OpaqueFunction in capstone.launch.py' in done.stdout, report
    assert any('not started because of a false condition: sim_watchdog' in line
               for line in met), report  # started with sim:=false only


def test_the_running_capstone_meets_its_spec(ros_env):
    """What the lesson runs: the default launch, checked once both turtles reached a
    waypoint (every node up, pose -> command chain working).  The running check runs
    as `speccheck live` in the sourced environment, which imports the
    capstone's message types as the lesson's kernel does."""
    spec = speccheck.load_spec(SPEC)
    with labkit.launch(PACKAGE, LAUNCH, env=ros_env, cwd=paths.WORKSPACE) as run:
        for robot in ROBOTS:
            run.wait_for_output(rf'\[{robot}\.patrol_planner\]: Waypoint reached',
                                timeout=HANG_GUARD)
        done = subprocess.run(
            [sys.executable, '-m', 'speccheck', 'live', str(SPEC), '--window', '3'],
            env=ros_env, capture_output=True, text=True, timeout=120, check=False)
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    report = done.stdout + done.stderr
    assert still_running and exit_code == 0, output
    assert 'process has died' not in output, output
    assert done.returncode == 0, report
    assert not [line for line in done.stdout.splitlines() if line.startswith('  FAILED')]
    met = [line.strip().removeprefix('met').strip() for line in done.stdout.splitlines()
           if line.startswith('  met')]
    for node in spec.nodes:
        assert f'node {node.name}: running' in met, report
    for topic in spec.topics:
        assert any(line.startswith(f'topic {topic.name}: type: ') for line in met), report
    for robot in ROBOTS:
        assert any(line.startswith(f'topic /{robot}/wall_reading: rate 7..13 Hz')
                   for line in met), report


def test_exercise_defect_differs_from_r9_only_in_turtle3s_configuration(ros_env):
    """The planted defect of exercise 7.1.1 is what its check says: every node and
    topic of R9 there and wired, only turtle3's route and stop distance turtle4's."""
    # --timeout 60: the default 20 s wait for the 19 nodes ran out once under CI load
    done = subprocess.run(
        [sys.executable, '-m', 'speccheck', 'live', str(EXERCISE_SPEC), str(DEFECT),
         '--timeout', '60'],
        env=ros_env, cwd=paths.WORKSPACE, capture_output=True, text=True, timeout=180,
        check=False)
    report = done.stdout + done.stderr
    failed = [line.strip() for line in done.stdout.splitlines() if line.startswith('  FAILED')]
    assert done.returncode == 1, report
    assert len(failed) == 2, report
    assert 'node /turtle3/patrol_planner: parameter waypoints: value [1.5, 1.5, 9.5, 1.5]' \
        in failed[0], report
    assert 'node /turtle3/safety_monitor: parameter stop_distance: value 1.0' in failed[1], report


def test_every_launch_file_the_lesson_shows_is_tested():
    shown = launch_files_included_by(LESSON)
    assert shown, f'{LESSON.name} shows no launch file'
    assert shown <= {(PACKAGE, LAUNCH)}, f'launch files shown but not tested: {sorted(shown)}'
