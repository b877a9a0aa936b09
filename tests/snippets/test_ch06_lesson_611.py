"""Launch files of lesson 6.11 (one system, three formats) start the nodes,
namespaces, parameters and topics the lesson says, in every format, and its
mistakes fail with the errors the lesson shows.

Each launch file is started as the lesson starts it (``ros2 launch PKG FILE
name:=value``, through labkit); its nodes are awaited in the ROS graph, the
graph is read until it shows the expected wiring (endpoints are discovered
after their nodes), every node's parameters are read over its parameter
services, and the launch is stopped with Ctrl+C.  The Python, XML and YAML
bringups are held to one expectation, so the three can only pass together.
"""
from __future__ import annotations

import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import labkit
import pytest
from textbook import paths
from textbook.myst import fences

from ._launch_log import ENDED, STARTED
from ._wiring import Wiring, settled_graph, wiring_of

LESSON = paths.LESSONS / 'ch06/L3/11_one_system_three_formats.md'
PACKAGE = 'my_robot_pkg'
LAUNCH = paths.SNIPPETS / PACKAGE / 'launch'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit


@dataclass(frozen=True)
class Case:
    """One launch as the lesson runs it, and the system it must start."""

    launch_file: str
    arguments: dict[str, str]
    topics: Wiring
    nodes: dict[str, dict[str, Any]]  # node -> {parameter: value (and type)}
    package: str = PACKAGE

    @property
    def id(self) -> str:
        given = ' '.join(f'{k}:={v}' for k, v in self.arguments.items())
        return f'{self.launch_file} {given}'.strip()


def _robot(ns: str, rate: float, controller: bool, topic: str = 'range',
           window: int = 5, controller_params: dict[str, Any] | None = None,
           ) -> tuple[Wiring, dict[str, dict[str, Any]]]:
    """Wiring and parameters of one robot of the bringup in namespace `ns`."""
    wiring: Wiring = {
        f'/{ns}/{topic}': ((f'/{ns}/sensor_publisher',), (f'/{ns}/data_processor',)),
        f'/{ns}/distance_filtered': ((f'/{ns}/data_processor',),
                                     (f'/{ns}/robot_controller',) if controller else ())}
    nodes: dict[str, dict[str, Any]] = {f'/{ns}/sensor_publisher': {'publish_rate': rate},
                                        f'/{ns}/data_processor': {'window_size': window}}
    if controller:
        wiring[f'/{ns}/cmd_vel'] = ((f'/{ns}/robot_controller',), ())
        nodes[f'/{ns}/robot_controller'] = controller_params or {
            'robot_name': ns, 'max_linear_speed': 0.8, 'update_rate': 20.0}
    return wiring, nodes


def _merge(*robots: tuple[Wiring, dict[str, dict[str, Any]]]) -> dict[str, Any]:
    topics: Wiring = {}
    nodes: dict[str, dict[str, Any]] = {}
    for robot_topics, params in robots:
        topics.update(robot_topics)
        nodes.update(params)
    return {'topics': topics, 'nodes': nodes}


DEFAULTS = _merge(_robot('robot1', 2.0, True))
OVERRIDDEN = _merge(_robot('robot2', 5.0, False))
OVERRIDES = {'robot_name': 'robot2', 'sensor_rate': '5.0', 'use_controller': 'false'}
FLEET = _merge(_robot('robot1', 2.0, True), _robot('robot2', 5.0, False))
BRINGUPS = ('bringup_formats.launch.py', 'bringup_formats.launch.xml',
            'bringup_formats.launch.yaml')


def _sensors(count: int) -> dict[str, Any]:
    names = tuple(f'/sensor_{n}' for n in range(1, count + 1))
    return {'topics': {'/distance': (names, ())},
            'nodes': {name: {'publish_rate': 2.0} for name in names}}


ROVER = _merge(_robot('rover1', 5.0, True, topic='scan_range', window=3,
                      controller_params={'robot_name': 'rover1', 'max_linear_speed': 1.2}))

CASES = [
    *(Case(name, {}, **DEFAULTS) for name in BRINGUPS),
    *(Case(name, OVERRIDES, **OVERRIDDEN) for name in BRINGUPS),
    Case('fleet_xml_includes_py.launch.xml', {}, **FLEET),
    Case('fleet_py_includes_xml.launch.py', {}, **FLEET),
    Case('sensor_array.launch.py', {}, **_sensors(3)),
    Case('sensor_array.launch.py', {'sensor_count': '5'}, **_sensors(5)),
    # XML has no loop: three conditional nodes, so 5 asked for still gives 3.
    Case('sensor_array.launch.xml', {'sensor_count': '5'}, **_sensors(3)),
    Case('sensor_array.launch.xml', {'sensor_count': '2'}, **_sensors(2)),
    # The Python file the exercise's twin is compared with, and the twin (solution).
    Case('twin_rover.launch.py', {}, **ROVER),
    Case(str(paths.SNIPPETS / 'ch06_solutions/launch/ex611_rover.launch.xml'), {}, **ROVER,
         package=''),
]


def _typed(params: dict[str, Any], names: list[str]) -> dict[str, tuple[str, Any]]:
    """name -> (type, value): 5 and 5.0 are different answers here."""
    return {name: (type(params.get(name)).__name__, params.get(name)) for name in names}


def _start(case: Case, ros_env: dict[str, str]) -> labkit.Background:
    where = (case.package, case.launch_file) if case.package else (case.launch_file,)
    return labkit.launch(*where, launch_arguments=case.arguments, env=ros_env,
                         cwd=paths.WORKSPACE)


@pytest.mark.parametrize('case', CASES, ids=lambda case: case.id)
def test_launch_starts_its_system(case: Case, ros_env):
    with _start(case, ros_env) as run:
        run.wait_for_nodes(list(case.nodes), timeout=HANG_GUARD)
        expected = {name: (tuple(sorted(pubs)), tuple(sorted(subs)))
                    for name, (pubs, subs) in case.topics.items()}
        # only the topics this system uses: a node SIGKILLed by an earlier test on this
        # worker (the Fast DDS shutdown hang) stays on the graph until its lease ends
        snapshot = settled_graph(expected, HANG_GUARD, only_expected=True)
        got = {node: _typed(labkit.read_parameters(node), list(wanted))
               for node, wanted in case.nodes.items()}
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    assert still_running, output
    assert 'process has died' not in output, output
    started = [m.group(1) for line in output.splitlines() if (m := STARTED.match(line))]
    assert len(started) == len(case.nodes), output  # no process beyond the expected nodes
    assert set(case.nodes) <= set(snapshot.nodes), output  # extra ones: ghosts (above)
    assert wiring_of(snapshot, expected, only_expected=True) == expected, str(snapshot)
    assert got == {node: _typed(wanted, list(wanted)) for node, wanted in case.nodes.items()}
    ended = [m.group(1) for line in output.splitlines() if (m := ENDED.match(line))]
    assert exit_code == 0 and sorted(ended) == sorted(started), output


def _ros2(ros_env: dict[str, str], *words: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(['ros2', *words], env=ros_env, cwd=paths.WORKSPACE,
                          capture_output=True, text=True, timeout=120, check=False)


def test_the_three_bringups_show_the_same_arguments(ros_env):
    shown = [_ros2(ros_env, 'launch', PACKAGE, name, '--show-args') for name in BRINGUPS]
    assert all(result.returncode == 0 for result in shown), shown
    python = shown[0].stdout
    for name in ('robot_name', 'sensor_rate', 'use_controller'):
        assert f"    '{name}':" in python, python
    assert "(default: 'robot1')" in python and "(default: '2.0')" in python, python
    assert [result.stdout for result in shown] == [python] * 3


# (file, error the lesson explains): each stops the launch before any process starts.
MISTAKES = [
    ('mistake_formats_undeclared.launch.xml',
     ["[ERROR] [launch]: Caught exception in launch (see debug for traceback): "
      "launch configuration 'sensor_rte' does not exist"]),
    ('mistake_formats_attribute.launch.xml',
     ['Caught multiple exceptions when trying to load file of format [xml]:',
      " - AttributeError: Attribute 'exec' of type '<class 'str'>' not found in Entity 'node'"]),
    ('mistake_formats_indent.launch.yaml',
     ['Caught multiple exceptions when trying to load file of format [yaml]:',
      ' - ParserError: while parsing a block mapping',
      "expected <block end>, but found '<block mapping start>'",
      'mistake_formats_indent.launch.yaml", line 33, column 8']),
    ('mistake_sensor_array_loop.launch.py',
     ['Caught multiple exceptions when trying to load file of format [py]:',
      " - TypeError: int() argument must be a string, a bytes-like object or a real number, "
      "not 'LaunchConfiguration'"]),
]


@pytest.mark.parametrize(('launch_file', 'lines'), MISTAKES, ids=[m[0] for m in MISTAKES])
def test_mistake_fails_with_the_error_the_lesson_explains(launch_file, lines, ros_env):
    result = _ros2(ros_env, 'launch', PACKAGE, launch_file)
    output = result.stdout + result.stderr
    assert result.returncode == 1, output
    assert 'process started' not in output, output
    for line in lines:
        assert line in output, output


def _launch_files_shown(lesson: Path) -> set[str]:
    """Launch files (any format) of my_robot_pkg that the lesson includes."""
    found = set()
    for fence in fences(lesson.read_text()):
        target = fence.argument.partition('#')[0]
        if fence.directive == 'snippet' and f'{PACKAGE}/launch/' in target:
            found.add(target.rpartition('/')[2])
    return found


TESTED = {case.launch_file for case in CASES} | {name for name, _ in MISTAKES}


def test_every_launch_file_the_lesson_shows_is_tested():
    shown = _launch_files_shown(LESSON)
    assert {'bringup_formats.launch.xml', 'bringup_formats.launch.yaml'} <= shown, shown
    assert shown <= TESTED, f'launch files shown but not tested: {sorted(shown - TESTED)}'


@pytest.mark.parametrize('pattern', ['bringup_formats.*', 'fleet_*', 'sensor_array.*',
                                     'mistake_formats_*', 'mistake_sensor_array_*',
                                     'twin_rover.*'])
def test_every_new_snippet_of_the_lesson_is_tested(pattern):
    files = {path.name for path in LAUNCH.glob(pattern)}
    assert files and files <= TESTED, sorted(files - TESTED)
