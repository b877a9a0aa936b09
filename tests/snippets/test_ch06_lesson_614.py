"""Lesson 6.14 (from a specification to a system): dock_watch_pkg's launch
files start the system its specs describe, and the spec checker gives the
verdicts the lesson shows, line for line.

The static check runs as a student's terminal runs it (`speccheck
static`); the running check with `speccheck.check_live` while labkit runs the
launch, after the planner has logged its first report (the chain battery_sim
-> battery_monitor -> dock_planner is connected then).  Expected values come
from the spec files themselves (read with `speccheck.load_spec`), so a spec
and the system can only change together.
"""
from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import labkit
import pytest
import speccheck
from textbook import paths

from ._shown_snippets import launch_files_included_by
from ._wiring import Wiring, settled_graph, wiring

LESSON = paths.LESSONS / 'ch06/L4/14_specification_to_system.md'
PACKAGE = 'dock_watch_pkg'
SOLUTION = paths.SNIPPETS / 'ch06_solutions' / 'launch' / 'ex614_dock_watch.launch.py'
SPECS = paths.SNIPPETS / PACKAGE / 'specs'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
#: the planner's first /battery_low message; its logger is `dock_planner` or `<ns>.dock_planner`
FIRST_REPORT = r'dock_planner\]: First report: battery ok'


def _spec(name: str) -> speccheck.Spec:
    return speccheck.load_spec(SPECS / name)


def _wiring_of(spec: speccheck.Spec) -> Wiring:
    return {topic.name: (tuple(sorted(topic.publishers)), tuple(sorted(topic.subscribers)))
            for topic in spec.topics}


def _static(spec: str, launch_file: str, env: dict[str, str],
            *arguments: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, '-m', 'speccheck', 'static', str(SPECS / spec), '--launch', PACKAGE,
         launch_file, *arguments], env=env, capture_output=True, text=True, timeout=120,
        check=False)


def _failed(output: str) -> list[str]:
    return [line.strip().removeprefix('FAILED').strip()
            for line in output.splitlines() if line.startswith('  FAILED')]


#: (spec, launch file) -> the requirements the static check fails, each with what it found
STATIC = {
    # The lesson's first attempt: a percentage for a fraction, '2' for a double.
    ('dock_watch.spec.yaml', 'dock_watch_first.launch.py'): {
        'argument battery_rate': "default '2', the spec says '2.0'",
        'node /battery_sim: parameter publish_rate': 'type integer (2), the spec says double',
        'node /battery_monitor: parameter low_threshold': 'value 20.0, the spec says 0.2'},
    ('dock_watch.spec.yaml', 'dock_watch.launch.py'): {},
    # The specification changed: exactly the changed and the new requirements fail.
    ('dock_watch_v2.spec.yaml', 'dock_watch.launch.py'): {
        'argument battery_rate': "default '2.0', the spec says '5.0'",
        'argument low_threshold': 'not declared',
        'node /battery_sim: parameter publish_rate': 'value 2.0, the spec says 5.0',
        'node /battery_monitor: parameter low_threshold': 'value 0.2, the spec says 0.25'},
    ('dock_watch_v2.spec.yaml', 'dock_watch_v2.launch.py'): {},
}


@pytest.mark.parametrize('spec_and_file', list(STATIC), ids=' '.join)
def test_static_check_gives_the_lessons_verdict(spec_and_file: tuple[str, str], ros_env):
    expected = STATIC[spec_and_file]
    done = _static(*spec_and_file, ros_env)
    report = done.stdout + done.stderr
    assert done.returncode == (1 if expected else 0), report
    failed = _failed(done.stdout)
    assert len(failed) == len(expected), report
    for requirement, evidence in expected.items():
        assert any(line.startswith(f'{requirement}: ') and evidence in line
                   for line in failed), f'{requirement}: {evidence} not in\n{report}'
    # Topic names are the programs' business: only the running check decides them.
    unchecked = [line for line in done.stdout.splitlines() if line.startswith('  not checked')]
    assert unchecked and all(' topic /' in line for line in unchecked), report


#: (launch file, arguments) -> (the spec the launch meets, the spec it is also held to and
#: the requirements of that one it fails)
LIVE = {
    ('dock_watch.launch.py', ()): (
        'dock_watch.spec.yaml', 'dock_watch_v2.spec.yaml',
        ['node /battery_sim: parameter publish_rate', 'node /battery_monitor: parameter '
         'low_threshold', 'topic /battery_state: rate', 'topic /battery_low: rate']),
    ('dock_watch_v2.launch.py', ()): ('dock_watch_v2.spec.yaml', 'dock_watch.spec.yaml', [
        'node /battery_sim: parameter publish_rate', 'node /battery_monitor: parameter '
        'low_threshold', 'topic /battery_state: rate', 'topic /battery_low: rate']),
}


@contextmanager
def _running(launch_file: str, arguments: dict[str, str], nodes: list[str], env,
             package: str = PACKAGE) -> Iterator[labkit.Background]:
    """The launch, once the chain battery_sim -> monitor -> planner is connected;
    stopped on the way out, also when the wait fails."""
    with labkit.launch(*([package, launch_file] if package else [launch_file]),
                       launch_arguments=arguments, env=env, cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(nodes, timeout=HANG_GUARD)
        run.wait_for_output(FIRST_REPORT, timeout=HANG_GUARD)
        yield run


@pytest.mark.parametrize('case', list(LIVE), ids=lambda case: case[0])
def test_running_system_meets_its_spec_and_fails_the_other_exactly_where_they_differ(
        case: tuple[str, tuple], ros_env):
    launch_file, arguments = case
    meets, other, fails = LIVE[case]
    spec, other_spec = _spec(meets), _spec(other)
    with _running(launch_file, dict(arguments), [node.name for node in spec.nodes],
                  ros_env) as run:
        snapshot = settled_graph(_wiring_of(spec), HANG_GUARD)
        report = speccheck.check_live(spec, window=3.0)
        other_report = speccheck.check_live(other_spec, window=3.0)
        still_running = run.running
        exit_code = run.stop()
    output = run.output()
    assert still_running and exit_code == 0, output
    assert 'process has died' not in output, output
    assert wiring(snapshot) == _wiring_of(spec), output
    assert report.ok, str(report)
    failed = [f.requirement for f in other_report.failures]
    assert len(failed) == len(fails), str(other_report)
    for prefix in fails:
        assert sum(r.startswith(prefix) for r in failed) == 1, f'{prefix}\n{other_report}'


def test_arguments_reach_the_nodes_as_doubles(ros_env):
    """`battery_rate:=4` (an integer on the command line) still gives the node a double."""
    arguments = {'battery_rate': '4', 'dock_x': '2', 'dock_y': '-1.5', 'low_threshold': '0.3'}
    nodes = ['/battery_sim', '/battery_monitor', '/dock_planner']
    with _running('dock_watch_v2.launch.py', arguments, nodes, ros_env) as run:
        got = {node: labkit.read_parameters(node) for node in nodes}
        exit_code = run.stop()
    assert exit_code == 0, run.output()
    assert got['/battery_sim']['publish_rate'] == 4.0
    assert isinstance(got['/battery_sim']['publish_rate'], float)
    assert got['/battery_monitor']['low_threshold'] == 0.3
    assert (got['/dock_planner']['dock_x'], got['/dock_planner']['dock_y']) == (2.0, -1.5)
    assert isinstance(got['/dock_planner']['dock_x'], float)


@pytest.mark.parametrize('node, parameter, value', [
    ('battery_monitor', 'low_threshold', '20.0'),
    ('battery_sim', 'publish_rate', '0.0'),
    ('dock_planner', 'dock_x', '1000.0'),
])
def test_a_value_outside_the_declared_range_stops_the_node(node: str, parameter: str,
                                                          value: str, ros_env):
    done = subprocess.run(
        [paths.executable('ros2'), 'run', PACKAGE, node, '--ros-args', '-p',
         f'{parameter}:={value}'], env=ros_env, capture_output=True, text=True,
        timeout=HANG_GUARD, check=False)
    output = done.stdout + done.stderr
    assert done.returncode != 0, output
    assert f'Parameter {parameter} out of range' in output, output



@pytest.mark.parametrize('robot', ['scout', 'rover'])
def test_exercise_solution_meets_the_robot_spec_for_its_argument(robot: str, ros_env,
                                                                 tmp_path: Path):
    """The solution the lesson shows: every node and topic in /<robot>/."""
    text = (SPECS / 'dock_watch_robot.spec.yaml').read_text().replace('/scout/', f'/{robot}/')
    (tmp_path / 'robot.spec.yaml').write_text(text)
    spec = speccheck.load_spec(tmp_path / 'robot.spec.yaml')
    arguments = {} if robot == 'scout' else {'robot': robot}
    with _running(str(SOLUTION), arguments, [node.name for node in spec.nodes], ros_env,
                  package='') as run:
        settled_graph(_wiring_of(spec), HANG_GUARD)
        report = speccheck.check_live(spec, window=3.0)
        exit_code = run.stop()
    assert exit_code == 0, run.output()
    assert report.ok, str(report)
    assert all(node.name.startswith(f'/{robot}/') for node in spec.nodes)


def test_every_launch_file_the_lesson_shows_is_tested():
    tested = {(PACKAGE, name) for _spec_name, name in STATIC}
    tested |= {(PACKAGE, name) for name, _args in LIVE}
    tested.add(('ch06_solutions', SOLUTION.name))
    shown = launch_files_included_by(LESSON)
    assert shown, f'{LESSON.name} shows no launch file'
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'
