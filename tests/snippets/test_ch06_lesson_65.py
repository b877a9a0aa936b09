"""Launch files of lesson 6.5 (namespaces and remapping) and its exercise
solution start the nodes they promise, in the namespaces they promise, wired
to the topics their remappings promise, with the parameters they promise.

Each launch file is started as the lesson starts it (``ros2 launch PKG FILE``,
through labkit); its nodes are awaited in the ROS graph, the graph is read
(every topic with its publishers and subscribers, the default topics left
out), parameters are read over the nodes' parameter services, and the launch
is stopped with Ctrl+C.  The mistakes the lesson shows (a parameter file keyed
by the bare node name, an absolute name escaping the namespace, a remapping
that matches nothing) are held to the graph and values the lesson explains.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import labkit
import pytest
from labkit import checks
from textbook import paths

from ._launch_log import ENDED, STARTED
from ._shown_snippets import launch_files_included_by
from ._wiring import Wiring, settled_graph, wiring

LESSON = paths.LESSONS / 'ch06/L1/05_namespaces_and_remapping.md'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit


@dataclass(frozen=True)
class Case:
    """One launch as the lesson runs it, and the graph it must make."""

    package: str
    launch_file: str
    executables: tuple[str, ...]
    topics: Wiring
    # node (full name) -> {parameter: expected value}; the nodes the graph must hold
    nodes: dict[str, dict[str, Any]] = field(default_factory=dict)

    @property
    def id(self) -> str:
        return self.launch_file


def _robot(ns: str) -> Wiring:
    """The wiring of one robot (sensor -> processor -> controller) in namespace `ns`."""
    return {f'/{ns}/cmd_vel': ((f'/{ns}/robot_controller',), ()),
            f'/{ns}/distance': ((f'/{ns}/sensor_publisher',), (f'/{ns}/data_processor',)),
            f'/{ns}/distance_filtered': ((f'/{ns}/data_processor',),
                                         (f'/{ns}/robot_controller',))}


def _robot_nodes(ns: str, controller: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {f'/{ns}/sensor_publisher': {'publish_rate': 2.0},
            f'/{ns}/data_processor': {'window_size': 3},
            f'/{ns}/robot_controller': controller}


PIPELINE = ('data_processor', 'robot_controller', 'sensor_publisher')
DEFAULT_SPEED = {'robot_name': 'my_robot', 'max_linear_speed': 0.5}

CASES = [
    Case('my_robot_pkg', 'ns_robot1.launch.py', ('data_processor', 'sensor_publisher'),
         topics={'/robot1/distance': (('/robot1/sensor_publisher',), ('/robot1/data_processor',)),
                 '/robot1/distance_filtered': (('/robot1/data_processor',), ())},
         nodes={'/robot1/sensor_publisher': {'publish_rate': 2.0},
                '/robot1/data_processor': {'window_size': 3}}),
    Case('my_robot_pkg', 'ns_two_robots.launch.py', PIPELINE * 2,
         topics={**_robot('robot1'), **_robot('robot2')},
         nodes={**_robot_nodes('robot1', {'robot_name': 'alpha'}),
                **_robot_nodes('robot2', {'robot_name': 'bravo'})}),
    Case('my_robot_pkg', 'remap_two_sensors.launch.py',
         ('data_processor', 'sensor_publisher', 'sensor_publisher'),
         topics={'/ranges': (('/front_sensor', '/rear_sensor'), ('/data_processor',)),
                 '/distance_filtered': (('/data_processor',), ())},
         nodes={'/front_sensor': {}, '/rear_sensor': {}, '/data_processor': {}}),
    # SetRemap and PushRosNamespace end with their group: the controller keeps both defaults.
    Case('my_robot_pkg', 'remap_set_remap.launch.py', PIPELINE,
         topics={'/robot1/ranges': (('/robot1/sensor_publisher',), ('/robot1/data_processor',)),
                 '/robot1/distance_filtered': (('/robot1/data_processor',), ()),
                 '/distance_filtered': ((), ('/robot_controller',)),
                 '/cmd_vel': (('/robot_controller',), ())},
         nodes={'/robot1/sensor_publisher': {}, '/robot1/data_processor': {},
                '/robot_controller': {}}),
    # SetParameter ends with its group too: use_sim_time inside, the default outside; the
    # nodes on simulated time subscribe to /clock, which nobody publishes here.
    Case('my_robot_pkg', 'group_set_parameter.launch.py', PIPELINE,
         topics={'/robot1/distance': (('/robot1/sensor_publisher',), ('/robot1/data_processor',)),
                 '/robot1/distance_filtered': (('/robot1/data_processor',), ()),
                 '/distance_filtered': ((), ('/robot_controller',)),
                 '/cmd_vel': (('/robot_controller',), ()),
                 '/clock': ((), ('/robot1/sensor_publisher', '/robot1/data_processor'))},
         nodes={'/robot1/sensor_publisher': {'use_sim_time': True},
                '/robot1/data_processor': {'use_sim_time': True},
                '/robot_controller': {'use_sim_time': False}}),
    # Mistake: the processor's rule names "distances"; it matches nothing and changes nothing.
    Case('my_robot_pkg', 'remap_matches_nothing.launch.py',
         ('data_processor', 'sensor_publisher', 'sensor_publisher'),
         topics={'/ranges': (('/front_sensor', '/rear_sensor'), ()),
                 '/distance': ((), ('/data_processor',)),
                 '/distance_filtered': (('/data_processor',), ())},
         nodes={'/front_sensor': {}, '/rear_sensor': {}, '/data_processor': {}}),
    # Mistake: '/obstacle_distance' is absolute, so both robots share it.
    Case('my_robot_pkg', 'ns_absolute_escape.launch.py', PIPELINE * 2,
         topics={'/obstacle_distance': (('/robot1/data_processor', '/robot2/data_processor'),
                                        ('/robot1/robot_controller', '/robot2/robot_controller')),
                 **{topic: ends for topic, ends in {**_robot('robot1'), **_robot('robot2')}.items()
                    if not topic.endswith('distance_filtered')}},
         nodes={**_robot_nodes('robot1', DEFAULT_SPEED), **_robot_nodes('robot2', DEFAULT_SPEED)}),
    # Mistake: a file keyed by the bare name misses /robot1/robot_controller;
    # /**/robot_controller reaches /robot2/robot_controller.
    Case('my_robot_pkg', 'ns_param_keys.launch.py', ('robot_controller', 'robot_controller'),
         topics={'/robot1/cmd_vel': (('/robot1/robot_controller',), ()),
                 '/robot1/distance_filtered': ((), ('/robot1/robot_controller',)),
                 '/robot2/cmd_vel': (('/robot2/robot_controller',), ()),
                 '/robot2/distance_filtered': ((), ('/robot2/robot_controller',))},
         nodes={'/robot1/robot_controller': DEFAULT_SPEED,
                '/robot2/robot_controller': {'robot_name': 'bravo', 'max_linear_speed': 0.8}}),
    # exercise solution
    Case('ch06_solutions', 'ex65_two_sensors.launch.py',
         ('data_processor', 'sensor_publisher', 'sensor_publisher'),
         topics={'/ranges': (('/front/sensor_publisher', '/rear/sensor_publisher'),
                             ('/data_processor',)),
                 '/distance_filtered': (('/data_processor',), ())},
         nodes={'/front/sensor_publisher': {}, '/rear/sensor_publisher': {},
                '/data_processor': {}}),
]


def _values(params: dict[str, Any], names: list[str]) -> dict[str, Any]:
    return {name: params.get(name) for name in names}


@pytest.mark.parametrize('case', CASES, ids=lambda case: case.id)
def test_launch_makes_its_graph(case: Case, ros_env):
    with labkit.launch(case.package, case.launch_file, env=ros_env, cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(list(case.nodes), timeout=HANG_GUARD)
        expected = {name: (tuple(sorted(pubs)), tuple(sorted(subs)))
                    for name, (pubs, subs) in case.topics.items()}
        snapshot = settled_graph(expected, HANG_GUARD)
        got = {node: _values(labkit.read_parameters(node), list(wanted))
               for node, wanted in case.nodes.items()}
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    assert still_running, output
    assert 'process has died' not in output, output
    started = sorted(m.group(1) for line in output.splitlines() if (m := STARTED.match(line)))
    assert started == sorted(case.executables), output
    assert sorted(snapshot.nodes) == sorted(case.nodes), output
    assert wiring(snapshot) == expected, str(snapshot)
    assert got == case.nodes, output
    ended = sorted(m.group(1) for line in output.splitlines() if (m := ENDED.match(line)))
    assert exit_code == 0 and ended == started, output


def _graded_by_exercise_checks() -> set[tuple[str, str]]:
    """Solution launch files that find the student's package (FindPackageShare(
    'my_ws_exercises')): they run only as a student's package, which
    tests/exercises builds and launches, so they are tested there."""
    return {('ch06_solutions', Path(relative).name)
            for exercise in checks.EXERCISES.values() for relative in exercise.files
            if relative.startswith('launch/')
            and 'my_ws_exercises' in exercise.solution(relative).read_text()}


def test_every_launch_file_the_lesson_shows_is_tested():
    tested = {(case.package, case.launch_file) for case in CASES} | _graded_by_exercise_checks()
    shown = launch_files_included_by(LESSON)
    assert shown, f'{LESSON.name} shows no launch file'
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'


def test_every_new_snippet_of_the_lesson_is_tested():
    """Every ns_*/remap_* launch file of my_robot_pkg and every ex65 solution."""
    folder = paths.SNIPPETS / 'my_robot_pkg' / 'launch'
    files = {('my_robot_pkg', p.name) for pattern in ('ns_*.launch.py', 'remap_*.launch.py')
             for p in folder.glob(pattern)}
    files |= {('ch06_solutions', p.name)
              for p in (paths.SNIPPETS / 'ch06_solutions' / 'launch').glob('ex65_*.launch.py')}
    tested = {(case.package, case.launch_file) for case in CASES} | _graded_by_exercise_checks()
    assert files and files <= tested, sorted(files - tested)
