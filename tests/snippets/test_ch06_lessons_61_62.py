"""Launch files of lessons 6.1 and 6.2 and their exercise solutions start the
nodes they promise, with the parameters they promise; the launch files that
show a mistake fail with the error the lesson explains.

Every launch file is started the way a student starts it (``ros2 launch PKG
FILE``) and stopped the way a student stops it (Ctrl+C: SIGINT to the
foreground process group).  The nodes and their parameters are read from
the ROS graph with rclpy, as ``ros2 node list`` / ``ros2 param get`` would.
"""
from __future__ import annotations

import os
import signal
import subprocess
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
import rclpy
from labkit import checks, observer
from rcl_interfaces.srv import GetParameters
from rclpy.context import Context
from rclpy.node import Node as RclpyNode
from rclpy.parameter import parameter_value_to_python
from textbook import paths

from .._polling import poll
from .._terminal import terminal_popen
from ._shown_snippets import launch_files_included_by

LESSONS = [paths.LESSONS / 'ch06/L1/01_anatomy_of_a_launch_file.md',
           paths.LESSONS / 'ch06/L1/02_parameters_in_launch_files.md']
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit


@dataclass(frozen=True)
class Case:
    """One launch: what to type, and what must be running afterwards."""

    package: str
    launch_file: str
    arguments: tuple[str, ...] = ()
    # node (full name) -> {parameter: expected value}; {} only checks the node is up
    nodes: dict[str, dict[str, Any]] = field(default_factory=dict)

    @property
    def id(self) -> str:
        return ' '.join((self.launch_file, *self.arguments))


ROBOT_PARAMS_YAML = {'robot_name': 'scout', 'update_rate': 20.0, 'max_linear_speed': 0.8,
                     'max_angular_speed': 1.5, 'enabled_sensors': ['lidar'],
                     'sensors.lidar.topic': 'front_scan', 'sensors.lidar.range_max': 8.0,
                     'sensors.camera.enabled': False}

RUNNING = [
    # lesson 6.1
    Case('my_robot_pkg', 'robot_system.launch.py',
         nodes={'/sensor_publisher': {'publish_rate': 2.0},
                '/data_processor': {'window_size': 3}}),
    Case('my_robot_pkg', 'print_buffered.launch.py', nodes={'/print_counter': {}}),
    Case('my_robot_pkg', 'print_unbuffered.launch.py',
         nodes={'/tty_counter': {}, '/unbuffered_counter': {}}),
    # lesson 6.2
    Case('my_robot_pkg', 'controller_params.launch.py',
         nodes={'/sensor_publisher': {'publish_rate': 4.0},
                '/data_processor': {'window_size': 5},
                '/robot_controller': {'robot_name': 'rover', 'update_rate': 5.0,
                                      'max_linear_speed': 0.3, 'enabled_sensors': ['lidar'],
                                      'sensors.camera.enabled': True}}),
    Case('my_robot_pkg', 'controller_yaml.launch.py',
         nodes={'/robot_controller': ROBOT_PARAMS_YAML}),
    Case('my_robot_pkg', 'layered_params.launch.py',
         nodes={'/sensor_publisher': {'publish_rate': 1.0},
                '/robot_controller': {**ROBOT_PARAMS_YAML, 'max_linear_speed': 0.2,
                                      'robot_name': 'scout_2'}}),
    Case('my_robot_pkg', 'mistake_robot_name_arg.launch.py', ('robot_name:=rover',),
         nodes={'/robot_controller': {'robot_name': 'rover'}}),
    Case('my_robot_pkg', 'robot_name_arg.launch.py', ('robot_name:=042',),
         nodes={'/robot_controller': {'robot_name': '042'}}),
    # exercise solutions
    Case('ch06_solutions', 'ex61_full_pipeline.launch.py',
         nodes={'/sensor_publisher': {}, '/data_processor': {}, '/robot_controller': {}}),
    Case('ch06_solutions', 'ex61_front_sensor.launch.py',
         nodes={'/front_sensor': {'publish_rate': 2.0}, '/data_processor': {}}),
    # (the 6.2 exercises run in the student's package: tests/exercises checks them)
]

# (case, exit code of `ros2 launch` or None when no golden records it, lines the output
# must contain): launch ends by itself.
FAILING = [
    # lesson 6.1: nothing starts, launch reports the missing executable
    (Case('my_robot_pkg', 'mistake_executable_name.launch.py'), 1,
     ["[ERROR] [launch]: Caught exception in launch (see debug for traceback): executable "
      "'sensor_publisher.py' not found on the libexec directory '"]),
    # lesson 6.2: the only node refuses its parameter and dies
    (Case('my_robot_pkg', 'mistake_integer_rate.launch.py'), None,
     ["[robot_controller-1] rclpy.exceptions.InvalidParameterTypeException: Trying to set "
      "parameter 'update_rate' to '2' of type 'INTEGER', expecting type 'DOUBLE': update_rate",
      '[ERROR] [robot_controller-1]: process has died [pid ']),
    (Case('my_robot_pkg', 'mistake_robot_name_arg.launch.py', ('robot_name:=042',)), None,
     ["[robot_controller-1] rclpy.exceptions.InvalidParameterTypeException: Trying to set "
      "parameter 'robot_name' to '34' of type 'INTEGER', expecting type 'STRING': robot_name",
      '[ERROR] [robot_controller-1]: process has died [pid ']),
]


@pytest.fixture
def graph():
    """An rclpy node in this test's ROS domain, to look at the graph."""
    context = Context()
    rclpy.init(context=context)
    node = rclpy.create_node('ch06_test_observer', context=context)
    yield node
    node.destroy_node()
    rclpy.shutdown(context=context)


def _command(case: Case) -> list[str]:
    return ['ros2', 'launch', case.package, case.launch_file, *case.arguments]


def _stop(proc: subprocess.Popen) -> str:
    """Ctrl+C as a terminal sends it (to the whole process group); returns the output."""
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGINT)
    try:
        out, _ = proc.communicate(timeout=HANG_GUARD)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        pytest.fail(f'launch did not stop on Ctrl+C:\n{out}')
    return out


@contextmanager
def launched(case: Case, ros_env: dict[str, str]):
    """``ros2 launch ...`` running in its own process group, with a terminal as its
    stdin as in a shell (so Ctrl+C to the group is a terminal's); yields the Popen."""
    proc = terminal_popen(_command(case), env=ros_env, cwd=paths.WORKSPACE,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          start_new_session=True)
    try:
        yield proc
    finally:
        proc.output = _stop(proc)


def _wait_for_nodes(graph: RclpyNode, names: set[str], proc: subprocess.Popen) -> set[str]:
    """Full names of the nodes in ``names`` that appeared before the launch ended."""
    def seen() -> set[str]:
        return {f"{ns.rstrip('/')}/{name}" for name, ns in graph.get_node_names_and_namespaces()}

    poll(lambda: names <= seen(), HANG_GUARD, stop=lambda: proc.poll() is not None)
    return names & seen()


def _get_parameters(node: str, names: list[str]) -> dict[str, Any]:
    """What ``ros2 param get NODE NAME`` asks: the node's get_parameters service
    (called through labkit's observer, the tests' one service-call helper)."""
    response = observer.observer().read(GetParameters, f'{node}/get_parameters',
                                        GetParameters.Request(names=names), HANG_GUARD)
    assert response is not None, f'{node}: get_parameters did not answer'
    values = [parameter_value_to_python(v) for v in response.values]
    return dict(zip(names, values, strict=True))


def _normalized(value: Any) -> Any:
    return list(value) if isinstance(value, (list, tuple)) or hasattr(value, 'tolist') else value


@pytest.mark.parametrize('case', RUNNING, ids=lambda case: case.id)
def test_launch_starts_nodes_with_their_parameters(case: Case, ros_env, graph):
    with launched(case, ros_env) as proc:
        up = _wait_for_nodes(graph, set(case.nodes), proc)
        got = {node: _get_parameters(node, list(expected)) if expected else {}
               for node, expected in case.nodes.items() if node in up}
    assert up == set(case.nodes), f'nodes missing: {set(case.nodes) - up}\n{proc.output}'
    got = {node: {k: _normalized(v) for k, v in params.items()} for node, params in got.items()}
    assert got == case.nodes, proc.output
    assert 'process has died' not in proc.output.split('user interrupted')[0], proc.output


@pytest.mark.parametrize('case,code,expected', FAILING, ids=lambda v: getattr(v, 'id', ''))
def test_mistake_is_reported_and_launch_ends(case: Case, code: int | None, expected: list[str],
                                             ros_env):
    proc = subprocess.Popen(_command(case), env=ros_env, cwd=paths.WORKSPACE,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True)
    try:
        # Nothing is left running after the mistake, so launch ends by itself.
        out, _ = proc.communicate(timeout=HANG_GUARD)
    except subprocess.TimeoutExpired:
        out = _stop(proc)
        pytest.fail(f'launch kept running after the mistake:\n{out}')
    for line in expected:
        assert line in out, out
    if code is not None:
        assert proc.returncode == code, out


def _graded_solutions() -> set[tuple[str, str]]:
    """Solution launch files of exercises: tests/exercises runs them in a student's package."""
    return {(exercise.solutions, Path(f).name) for exercise in checks.EXERCISES.values()
            for f in exercise.files if f.endswith('.launch.py')}


@pytest.mark.parametrize('lesson', LESSONS, ids=lambda p: p.name)
def test_every_launch_file_a_lesson_shows_is_tested(lesson):
    tested = {(case.package, case.launch_file) for case in RUNNING} | _graded_solutions()
    tested |= {(case.package, case.launch_file) for case, _, _ in FAILING}
    shown = launch_files_included_by(lesson)
    assert shown, f'{lesson.name} shows no launch file'
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'


def test_every_solution_launch_file_of_61_62_is_tested():
    folder = paths.SNIPPETS / 'ch06_solutions' / 'launch'
    solutions = {p.name for p in folder.glob('ex6[12]_*.launch.py')}
    tested = {case.launch_file for case in RUNNING if case.package == 'ch06_solutions'}
    tested |= {name for package, name in _graded_solutions() if package == 'ch06_solutions'}
    assert solutions and solutions <= tested, sorted(solutions - tested)
