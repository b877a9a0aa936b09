"""Launch files of lessons 6.3 and 6.4 start the nodes they promise (and no
others), with the parameters they promise; the mistakes the lessons show
fail with the messages the lessons explain.  (The exercise solutions are
graded in the student's package by labkit.checks: tests/exercises.)

Each launch file is started as the lesson starts it (``ros2 launch PKG FILE
name:=value ...``, through labkit), its nodes are awaited in the ROS graph,
their parameters read over their parameter services, and it is stopped with
Ctrl+C.
"""
from __future__ import annotations

import re
import subprocess
from dataclasses import dataclass, field
from typing import Any

import labkit
import pytest
from labkit import checks
from textbook import paths

from ._launch_log import STARTED
from ._shown_snippets import launch_files_included_by

LESSONS = [paths.LESSONS / 'ch06/L1/03_launch_arguments_and_substitutions.md',
           paths.LESSONS / 'ch06/L1/04_packaging_launch_and_config_files.md']
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
USER_LOG = re.compile(r'^\[INFO\] \[launch\.user\]: (.*)$')


@dataclass(frozen=True)
class Case:
    """One launch as a lesson runs it, and what must be running afterwards."""

    package: str
    launch_file: str
    arguments: dict[str, str] = field(default_factory=dict)
    # node (full name) -> {parameter: expected value}
    nodes: dict[str, dict[str, Any]] = field(default_factory=dict)
    # LogInfo messages ([launch.user]) that must appear, in this order
    log: tuple[str, ...] = ()

    @property
    def id(self) -> str:
        return ' '.join([self.launch_file, *(f'{k}:={v}' for k, v in self.arguments.items())])

    @property
    def executables(self) -> list[str]:
        """Executables whose processes launch must start: one per expected node."""
        return sorted(node.rsplit('/', 1)[-1] for node in self.nodes)


ROBOT_PARAMS_YAML = {'robot_name': 'scout', 'update_rate': 20.0, 'max_linear_speed': 0.8,
                     'enabled_sensors': ['lidar'], 'sensors.lidar.topic': 'front_scan'}

RUNNING = [
    # lesson 6.3
    Case('my_robot_pkg', 'robot_args.launch.py', {'robot_name': 'my_bot', 'sim_mode': 'false'},
         nodes={'/robot_controller': {'robot_name': 'my_bot', 'max_linear_speed': 0.5}},
         log=('Robot my_bot, sim_mode false, max_speed 0.5',)),
    Case('my_robot_pkg', 'robot_args.launch.py',
         nodes={'/robot_controller': {'robot_name': 'scout', 'max_linear_speed': 0.5}},
         log=('Robot scout, sim_mode true, max_speed 0.5',)),
    Case('my_robot_pkg', 'conditional_sensors.launch.py',
         nodes={'/sensor_publisher': {'publish_rate': 2.0},
                '/data_processor': {'window_size': 2},
                '/robot_controller': {'robot_name': 'my_robot'}}),
    Case('my_robot_pkg', 'conditional_sensors.launch.py',
         {'sim_mode': 'false', 'controller': 'manual', 'sensor_rate': '5.0'},
         nodes={'/data_processor': {'window_size': 5}},
         log=('sim_mode is false: no simulated sensor, start the driver of the real one',
              'controller is manual: no robot_controller, drive the robot yourself')),
    Case('my_robot_pkg', 'robot_instance.launch.py', {'robot_ns': 'robot1'},
         nodes={'/robot1/robot_controller': {'robot_name': 'scout'}},
         log=('Starting controller of scout in namespace /robot1',)),
    # The surprise the lesson shows: robot2 inherits robot1's name (Jazzy, 08_include).
    Case('my_robot_pkg', 'bringup_twice.launch.py',
         nodes={'/robot1/robot_controller': {'robot_name': 'alpha'},
                '/robot2/robot_controller': {'robot_name': 'alpha'}},
         log=('Starting controller of alpha in namespace /robot1',
              'Starting controller of alpha in namespace /robot2')),
    # lesson 6.4
    Case('my_robot_pkg', 'controller_yaml.launch.py',
         nodes={'/robot_controller': ROBOT_PARAMS_YAML}),
    Case('my_robot_pkg', 'controller_yaml_python.launch.py',
         nodes={'/robot_controller': ROBOT_PARAMS_YAML}),
]

# (case, the message `ros2 launch` must print): each ends by itself with exit code 1.
FAILING = [
    (Case('my_robot_pkg', 'robot_args.launch.py', {'sim_mode': 'False'}),
     "[ERROR] [launch]: Caught exception in launch (see debug for traceback): Argument "
     "\"sim_mode\" provided value \"False\" is not valid. Valid options are: ['true', 'false']"),
    (Case('my_robot_pkg', 'robot_instance.launch.py'),
     "[ERROR] [launch]: Caught exception in launch (see debug for traceback): Included launch "
     "description missing required argument 'robot_ns' (description: 'Namespace of this "
     "robot, e.g. robot1'), given: []"),
    (Case('my_robot_pkg', 'conditional_sensors.launch.py',
          {'sim_mode': 'false', 'use_filter': 'yes'}),
     "[ERROR] [launch]: Caught exception in launch (see debug for traceback): invalid condition "
     "expression, expected one of [true, 1, false, 0] but got 'yes', expanded from "
     "'<launch.substitutions.launch_configuration.LaunchConfiguration object at 0x"),
    (Case('my_robot_pkgg', 'robot_args.launch.py'),
     "Package 'my_robot_pkgg' not found: \"package 'my_robot_pkgg' not found, searching: ["),
    (Case('my_robot_pkg', 'no_such.launch.py'),
     "file 'no_such.launch.py' was not found in the share directory of package "
     "'my_robot_pkg' which is at '"),
]


def _values(params: dict[str, Any], names: list[str]) -> dict[str, Any]:
    return {name: list(params[name]) if isinstance(params.get(name), (list, tuple))
            else params.get(name) for name in names}


@pytest.mark.parametrize('case', RUNNING, ids=lambda case: case.id)
def test_launch_starts_its_nodes_with_their_parameters(case: Case, ros_env):
    with labkit.launch(case.package, case.launch_file, launch_arguments=case.arguments,
                       env=ros_env, cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(list(case.nodes), timeout=HANG_GUARD)
        got = {node: _values(labkit.read_parameters(node), list(expected))
               for node, expected in case.nodes.items()}
        still_running = run.running
        output = run.output()
    assert still_running, output
    assert 'process has died' not in output, output
    started = sorted(m.group(1) for line in output.splitlines() if (m := STARTED.match(line)))
    assert started == case.executables, output
    assert got == case.nodes, output
    logged = [m.group(1) for line in output.splitlines() if (m := USER_LOG.match(line))]
    assert logged == list(case.log), output


@pytest.mark.parametrize('case,message', FAILING, ids=lambda v: getattr(v, 'id', ''))
def test_mistake_stops_the_launch_with_its_message(case: Case, message: str, ros_env):
    words = ['ros2', 'launch', case.package, case.launch_file,
             *(f'{k}:={v}' for k, v in case.arguments.items())]
    result = subprocess.run(words, env=ros_env, cwd=paths.WORKSPACE, capture_output=True,
                            text=True, timeout=HANG_GUARD)
    output = result.stdout + result.stderr
    assert result.returncode == 1, output
    assert message in output, output
    assert 'process started' not in output, output


def test_show_args_lists_defaults_descriptions_and_choices(ros_env):
    result = subprocess.run(['ros2', 'launch', 'my_robot_pkg', 'robot_args.launch.py',
                             '--show-args'], env=ros_env, capture_output=True, text=True,
                            timeout=HANG_GUARD)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "Arguments (pass arguments as '<name>:=<value>'):",
        '',
        "    'robot_name':",
        '        Name of the robot, used in the log of the controller',
        "        (default: 'scout')",
        '',
        "    'max_speed':",
        '        Top linear speed in m/s (a decimal number, e.g. 1.0)',
        "        (default: '0.5')",
        '',
        "    'sim_mode':",
        "        One of: ['true', 'false']",
        "        (default: 'true')",
    ]


@pytest.mark.parametrize('lesson', LESSONS, ids=lambda p: p.name)
def test_every_launch_file_a_lesson_shows_is_tested(lesson):
    tested = {(case.package, case.launch_file) for case in RUNNING}
    # exercise solutions (ch06_solutions) are graded by their checks, see the test below
    shown = {(package, name) for package, name in launch_files_included_by(lesson)
             if package != 'ch06_solutions'}
    assert shown, f'{lesson.name} shows no launch file'
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'


def test_every_solution_launch_file_of_63_64_is_graded_by_an_exercise_check():
    """The solutions run in the student's package, graded by labkit.checks (proven both
    ways in tests/exercises), not here."""
    folder = paths.SNIPPETS / 'ch06_solutions' / 'launch'
    solutions = {f'launch/{p.name}' for p in folder.glob('ex6[34]_*.launch.py')}
    graded = {f for exercise in checks.EXERCISES.values() for f in exercise.files}
    assert solutions and solutions <= graded, sorted(solutions - graded)
