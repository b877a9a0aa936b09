"""Checks of lesson 6.0 (Set up and check your environment): the two nodes
run by hand, started by one launch file, and then one setting changed.

They judge the running graph, the launch log and the sensor's real
parameter, never the text of the file.
"""
from __future__ import annotations

import re
from typing import Any

from labkit.errors import LabkitError
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, read_parameters

TALK_FILE = 'ex60_talk.launch.py'
FAST_FILE = 'ex60_fast_sensor.launch.py'
SENSOR, PROCESSOR = '/sensor_publisher', '/data_processor'
FAST_RATE = 5.0
#: What the processor declares; the exercise must leave it alone.
PROCESSOR_WINDOW = 3

PUBLISHING_AT = re.compile(r'\[sensor_publisher\]: Publishing distance readings on '
                           r'"[^"]*" at (?P<rate>\S+) Hz')
EXCEPTION = re.compile(r'^\[(?P<process>[^\]]+)\] \S*(?:Exception|Error): (?P<message>.+)$')


def _ros2_run(executable: str) -> str:
    return (f"add Node(package='my_robot_pkg', executable='{executable}', output='screen'), "
            f'the launch version of `ros2 run my_robot_pkg {executable}`')


def _two_nodes_talk(verdict: Verdict, run: LaunchProbe) -> bool:
    """Both nodes run once each, and readings go sensor -> /distance -> processor."""
    errors = [f"{m['process']}: {m['message']}" for line in run.lines
              if (m := EXCEPTION.match(line))]
    if errors:
        hint = (' Write a float with a decimal point (5.0, not 5).'
                if any('expecting type' in e for e in errors) else '')
        return verdict.fail(f'a node stopped while it started: {errors[-1]}.{hint}').passed
    if not requirements.launch_ran(verdict, run):
        return False
    ok = requirements.node_running(verdict, run, PROCESSOR, _ros2_run('data_processor'))
    ok = requirements.node_running(verdict, run, SENSOR, _ros2_run('sensor_publisher')) and ok
    ok = requirements.names_unique(verdict, run) and ok
    return requirements.topic_link(verdict, run, '/distance', SENSOR, PROCESSOR) and ok


def check_talk(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The two terminals of lesson 6.0 as one launch file."""
    if requirements.files_installed(verdict, package):
        _two_nodes_talk(verdict, probe(package, TALK_FILE, (SENSOR, PROCESSOR)))
    return verdict


def _read_both(snapshot: GraphSnapshot) -> dict[str, Any]:
    """node -> its parameters, or why they could not be read."""
    found: dict[str, Any] = {}
    for node in (SENSOR, PROCESSOR):
        try:
            found[node] = read_parameters(node) if node in snapshot.nodes else 'not running'
        except LabkitError as error:
            found[node] = str(error)
    return found


def _shown(value: Any) -> str:
    kind = {int: 'an integer', float: 'a float'}.get(type(value), type(value).__name__)
    return f'{value!r} ({kind})'


def check_fast_sensor(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The sensor got publish_rate 5.0 and started at 5 Hz; the processor is unchanged."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, FAST_FILE, (SENSOR, PROCESSOR), inspect=_read_both)
    if not _two_nodes_talk(verdict, run):
        return verdict
    sensor, processor = (run.inspected or {}).get(SENSOR), (run.inspected or {}).get(PROCESSOR)
    if not isinstance(sensor, dict) or not isinstance(processor, dict):
        return verdict.fail(f'could not read the parameters of the nodes: {run.inspected}')
    rate = sensor.get('publish_rate')
    verdict.expect(rate == FAST_RATE and type(rate) is float,
                   f'{SENSOR} has publish_rate {FAST_RATE}',
                   f"{SENSOR} got publish_rate {_shown(rate)}, expected {FAST_RATE}: give the "
                   f"sensor's Node parameters=[{{'publish_rate': {FAST_RATE}}}]")
    started = [m['rate'] for line in run.lines if (m := PUBLISHING_AT.search(line))]
    verdict.expect(
        bool(started) and float(started[-1]) == FAST_RATE,
        f'{SENSOR} started publishing at {started[-1] if started else "?"} Hz (its log)',
        f'{SENSOR} started publishing at {started[-1]} Hz (its first log line), not '
        f'{FAST_RATE} Hz' if started else
        f"{SENSOR} logged no \"Publishing distance readings\" line: keep output='screen'")
    window = processor.get('window_size')
    verdict.expect(window == PROCESSOR_WINDOW, f'{PROCESSOR} keeps window_size {window}',
                   f'{PROCESSOR} got window_size {window!r}, expected its default '
                   f'{PROCESSOR_WINDOW}: only the sensor changes')
    return verdict


EXERCISES = (
    Exercise('ex60_talk', 'Exercise 6.0.1 (two terminals in one file)',
             ('launch/' + TALK_FILE,), check_talk),
    Exercise('ex60_fast_sensor', 'Exercise 6.0.2 (a faster sensor)',
             ('launch/' + FAST_FILE,), check_fast_sensor),
)
