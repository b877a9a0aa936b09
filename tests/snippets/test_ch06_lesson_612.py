"""Launch files of lesson 6.12 (architecture patterns) start the nodes,
namespaces, parameters and topics the lesson says, and its costs are real:
the copied robot files differ where the lesson says, the unscoped composition
gives the controller the sensor's rate, and a robot without robot_name is
refused.

Each launch file is started as the lesson starts it (``ros2 launch PKG FILE
name:=value``, through labkit); its nodes are awaited in the ROS graph, the
graph is read until it shows the expected wiring, every node's parameters are
read over its parameter services, and the launch is stopped with Ctrl+C.
"""
from __future__ import annotations

import subprocess
from dataclasses import dataclass
from typing import Any

import labkit
import pytest
from textbook import paths
from textbook.myst import fences

from ._launch_log import ENDED, STARTED
from ._wiring import Wiring, settled_graph, wiring

LESSON = paths.LESSONS / 'ch06/L3/12_architecture_patterns.md'
PACKAGE = 'robot_bringup'
LAUNCH = paths.SNIPPETS / PACKAGE / 'launch'
SOLUTION = paths.SNIPPETS / 'ch06_solutions/launch/ex612_fleet.launch.py'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit

System = tuple[Wiring, dict[str, dict[str, Any]]]


@dataclass(frozen=True)
class Case:
    """One launch as the lesson runs it, and the system it must start."""

    launch_file: str
    arguments: dict[str, str]
    system: System
    package: str = PACKAGE

    @property
    def id(self) -> str:
        given = ' '.join(f'{k}:={v}' for k, v in self.arguments.items())
        return f'{self.launch_file.rpartition("/")[2]} {given}'.strip()


def _robot(ns: str, sensor_rate: float = 2.0, window: int = 5, control_rate: float = 20.0,
           max_speed: float = 0.5) -> System:
    """Wiring and parameters of one robot (the three subsystems) in namespace `ns`."""
    sensor, processor, controller = (f'/{ns}/sensor_publisher', f'/{ns}/data_processor',
                                     f'/{ns}/robot_controller')
    topics: Wiring = {f'/{ns}/distance': ((sensor,), (processor,)),
                      f'/{ns}/distance_filtered': ((processor,), (controller,)),
                      f'/{ns}/cmd_vel': ((controller,), ())}
    nodes = {sensor: {'publish_rate': sensor_rate},
             processor: {'window_size': window},
             controller: {'robot_name': ns, 'update_rate': control_rate,
                          'max_linear_speed': max_speed}}
    return topics, nodes


def _merge(*systems: System) -> System:
    topics: Wiring = {}
    nodes: dict[str, dict[str, Any]] = {}
    for robot_topics, robot_nodes in systems:
        topics.update(robot_topics)
        nodes.update(robot_nodes)
    return topics, nodes


def _fleet(count: int, prefix: str = 'robot', sensor_rate: float = 2.0) -> System:
    return _merge(*(_robot(f'{prefix}{n}', sensor_rate) for n in range(1, count + 1)))


SENSORS_ALONE: System = ({'/distance': (('/sensor_publisher',), ())},
                         {'/sensor_publisher': {'publish_rate': 2.0}})
PERCEPTION_ALONE: System = ({'/distance': ((), ('/data_processor',)),
                             '/distance_filtered': (('/data_processor',), ())},
                            {'/data_processor': {'window_size': 5}})
CONTROL_ALONE: System = ({'/distance_filtered': ((), ('/robot_controller',)),
                          '/cmd_vel': (('/robot_controller',), ())},
                         {'/robot_controller': {'robot_name': 'robot', 'update_rate': 20.0,
                                                'max_linear_speed': 0.5}})

CASES = [
    # Each subsystem runs on its own, with its own arguments' defaults.
    Case('sensors.launch.py', {}, SENSORS_ALONE),
    Case('perception.launch.py', {}, PERCEPTION_ALONE),
    Case('control.launch.py', {}, CONTROL_ALONE),
    # The composed robot, and every argument passed down to its subsystem.
    Case('robot.launch.py', {'robot_name': 'robot1'}, _robot('robot1')),
    Case('robot.launch.py', {'robot_name': 'robot2', 'sensor_rate': '5.0',
                             'control_rate': '10.0'},
         _robot('robot2', sensor_rate=5.0, control_rate=10.0)),
    Case('fleet.launch.py', {}, _fleet(2)),
    Case('fleet.launch.py', {'robot_count': '3'}, _fleet(3)),
    Case('fleet_pair.launch.xml', {}, _merge(_robot('robot1'), _robot('robot2', 5.0))),
    # The copies: robot 1 retuned, robot 2 not.
    Case('copy_robot1.launch.py', {}, _robot('robot1')),
    Case('copy_robot2.launch.py', {}, _robot('robot2', window=3, max_speed=0.8)),
    # Unscoped: the sensors' rate (2.0) reaches control, whose default is 20.0.
    Case('mistake_robot_unscoped.launch.py', {'robot_name': 'robot1'},
         _robot('robot1', control_rate=2.0)),
    # The exercise's solution, with both counts its check uses.
    Case(str(SOLUTION), {}, _fleet(2, 'scout', 5.0), package=''),
    Case(str(SOLUTION), {'robot_count': '3'}, _fleet(3, 'scout', 5.0), package=''),
]


def _typed(params: dict[str, Any], names: list[str]) -> dict[str, tuple[str, Any]]:
    """name -> (type, value): 5 and 5.0 are different answers here."""
    return {name: (type(params.get(name)).__name__, params.get(name)) for name in names}


@pytest.mark.parametrize('case', CASES, ids=lambda case: case.id)
def test_launch_starts_its_system(case: Case, ros_env):
    topics, nodes = case.system
    where = (case.package, case.launch_file) if case.package else (case.launch_file,)
    with labkit.launch(*where, launch_arguments=case.arguments, env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(list(nodes), timeout=HANG_GUARD)
        expected = {name: (tuple(sorted(pubs)), tuple(sorted(subs)))
                    for name, (pubs, subs) in topics.items()}
        snapshot = settled_graph(expected, HANG_GUARD)
        got = {node: _typed(labkit.read_parameters(node), list(wanted))
               for node, wanted in nodes.items()}
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    assert still_running, output
    assert 'process has died' not in output, output
    started = [m.group(1) for line in output.splitlines() if (m := STARTED.match(line))]
    assert len(started) == len(nodes), output  # no process beyond the expected nodes
    assert sorted(snapshot.nodes) == sorted(nodes), output
    assert wiring(snapshot) == expected, str(snapshot)
    assert got == {node: _typed(wanted, list(wanted)) for node, wanted in nodes.items()}
    ended = [m.group(1) for line in output.splitlines() if (m := ENDED.match(line))]
    assert exit_code == 0 and sorted(ended) == sorted(started), output


def test_a_robot_without_a_name_is_refused(ros_env):
    result = subprocess.run(['ros2', 'launch', PACKAGE, 'robot.launch.py'], env=ros_env,
                            cwd=paths.WORKSPACE, capture_output=True, text=True, timeout=120,
                            check=False)
    output = result.stdout + result.stderr
    assert result.returncode == 1, output
    assert 'process started' not in output, output
    assert ("[ERROR] [launch]: Caught exception in launch (see debug for traceback): Included "
            "launch description missing required argument 'robot_name'") in output, output


def test_the_bringup_package_owns_no_code(ws_install):
    """Launch and parameter files only: no Python module, no executable installed."""
    prefix = ws_install / PACKAGE
    assert (prefix / 'share' / PACKAGE / 'launch' / 'robot.launch.py').is_file()
    assert not (prefix / 'lib' / PACKAGE).exists()
    modules = [p for p in prefix.rglob('site-packages/*') if not p.name.endswith('-info')]
    assert modules == [], modules


TESTED = {case.launch_file for case in CASES} | {'robot.launch.py'}


def _launch_files_shown() -> set[str]:
    """Launch files (any format) of robot_bringup that the lesson includes."""
    found = set()
    for fence in fences(LESSON.read_text()):
        target = fence.argument.partition('#')[0]
        if fence.directive == 'snippet' and f'{PACKAGE}/launch/' in target:
            found.add(target.rpartition('/')[2])
    return found


def test_every_launch_file_the_lesson_shows_is_tested():
    shown = _launch_files_shown()
    assert {'robot.launch.py', 'fleet.launch.py', 'fleet_pair.launch.xml'} <= shown, shown
    assert shown <= TESTED, f'launch files shown but not tested: {sorted(shown - TESTED)}'


def test_every_launch_file_of_the_package_is_tested():
    files = {path.name for path in LAUNCH.glob('*.launch.*')}
    assert files and files <= TESTED, sorted(files - TESTED)
