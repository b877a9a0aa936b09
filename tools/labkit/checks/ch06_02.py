"""Checks of lesson 6.2 (Parameters in launch files).

They read what the running controller really got (its parameters, through
its parameter services, and the values it logs as it starts), never the
text of the student's files: any valid YAML or launch file passes.  The
start-up log matters because robot_controller reads its parameters once,
in its constructor; a value set later is stored but changes nothing.
"""
from __future__ import annotations

import re
from typing import Any

import yaml

from labkit.errors import LabkitError
from labkit.grading import requirements
from labkit.grading.exercise import SNIPPETS, Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, read_parameters

CONTROLLER = '/robot_controller'
TURTLE_YAML = 'config/ex62_turtle.yaml'
TURTLE_FILE = 'ex62_turtle.launch.py'
DEMO_FILE = 'ex62_turtle_demo.launch.py'
SCOUT_FILE = 'ex62_scout_5hz.launch.py'

#: What robot_controller declares (lesson 6.2's table): name -> default.
DEFAULTS: dict[str, Any] = {
    'robot_name': 'my_robot', 'update_rate': 10.0, 'max_linear_speed': 0.5,
    'max_angular_speed': 1.0, 'enabled_sensors': ['lidar', 'camera'],
    'sensors.lidar.enabled': True, 'sensors.lidar.topic': 'scan',
    'sensors.lidar.range_max': 12.0, 'sensors.camera.enabled': False,
    'sensors.camera.topic': 'image_raw', 'sensors.camera.range_max': 5.0,
}
#: Turtle's settings (Exercise 1); every other parameter keeps its default.
TURTLE: dict[str, Any] = {
    'robot_name': 'turtle', 'update_rate': 5.0, 'max_linear_speed': 0.2,
    'enabled_sensors': ['camera'], 'sensors.lidar.enabled': False,
    'sensors.camera.enabled': True, 'sensors.camera.topic': 'front_camera',
}
DEMO_SPEED = 0.35
SCOUT_RATE = 5.0
ROBOT_PARAMS = SNIPPETS / 'my_robot_pkg' / 'config' / 'robot_params.yaml'

STARTED_WITH = re.compile(r'\[robot_controller\]: Robot "[^"]*" starting with '
                          r'update_rate=(?P<rate>\S+) Hz')
EXCEPTION = re.compile(r'^\[[^\]]+\] \S*(?:Exception|Error): (?P<message>.+)$')


def _read_controller(snapshot: GraphSnapshot) -> dict[str, Any] | str:
    """The controller's parameters, or why they could not be read."""
    if CONTROLLER not in snapshot.nodes:
        return f'{CONTROLLER} is not running'
    try:
        return read_parameters(CONTROLLER)
    except LabkitError as error:
        return str(error)


def _shown(value: Any) -> str:
    kind = {bool: 'a boolean', int: 'an integer', float: 'a float', str: 'a string',
            list: 'a list'}.get(type(value), type(value).__name__)
    return f'{value!r} ({kind})'


def _same(got: Any, expected: Any) -> bool:
    return got == expected and type(got) is type(expected)


def flat(tree: dict[str, Any], prefix: str = '') -> dict[str, Any]:
    """{'sensors': {'lidar': {'topic': 'x'}}} -> {'sensors.lidar.topic': 'x'}."""
    out: dict[str, Any] = {}
    for key, value in tree.items():
        if isinstance(value, dict):
            out.update(flat(value, f'{prefix}{key}.'))
        else:
            out[f'{prefix}{key}'] = value
    return out


def controller_started(verdict: Verdict, run: LaunchProbe, launch_file: str) -> bool:
    """The controller runs; if it died, show the error it died of (e.g. a type error)."""
    errors = [match['message'] for line in run.lines if (match := EXCEPTION.match(line))]
    if errors:
        hint = (' Write floats with a decimal point (5.0, not 5) and lists in brackets.'
                if any('expecting type' in e for e in errors) else '')
        return verdict.fail(f'{CONTROLLER} of {launch_file} stopped while it started: '
                            f'{errors[-1]}.{hint}').passed
    if not requirements.launch_ran(verdict, run):
        return False
    return requirements.node_running(
        verdict, run, CONTROLLER,
        "start it with Node(package='my_robot_pkg', executable='robot_controller', "
        "name='robot_controller', output='screen')")


def parameters_read(verdict: Verdict, run: LaunchProbe) -> dict[str, Any] | None:
    if isinstance(run.inspected, dict):
        return run.inspected
    verdict.fail(f'could not read the parameters of {CONTROLLER}: {run.inspected}')
    return None


def expect_values(verdict: Verdict, got: dict[str, Any], expected: dict[str, Any],
                  source: str) -> bool:
    """One requirement per parameter; the message names the value, its type and its source."""
    ok = True
    for name, value in expected.items():
        value_got = got.get(name)
        ok = verdict.expect(
            _same(value_got, value), f'{CONTROLLER} has {name} = {value!r}',
            f'{CONTROLLER} got {name} {_shown(value_got)}, expected {value!r} from {source}'
        ) and ok
    return ok


def started_rate(run: LaunchProbe) -> str | None:
    """The update_rate the controller logged as it started: the rate its loop runs at."""
    rates = [match['rate'] for line in run.lines if (match := STARTED_WITH.search(line))]
    return rates[-1] if rates else None


def check_turtle(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Turtle's values reach the controller with the right types; the rest stay defaults."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, TURTLE_FILE, (CONTROLLER,), inspect=_read_controller)
    if not controller_started(verdict, run, TURTLE_FILE) or \
            (got := parameters_read(verdict, run)) is None:
        return verdict
    if all(got.get(name) == DEFAULTS[name] for name in TURTLE):
        return verdict.fail(
            f'none of the values of {TURTLE_YAML} reached {CONTROLLER} (it runs with all its '
            f'defaults, e.g. robot_name {got.get("robot_name")!r}): the first key of the file '
            'must be the name of the node, robot_controller, followed by ros__parameters')
    expect_values(verdict, got, TURTLE, TURTLE_YAML)
    expect_values(verdict, got, {k: v for k, v in DEFAULTS.items() if k not in TURTLE},
                  'the default')
    return verdict


def check_turtle_demo(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The demo launch = ex62_turtle.launch.py's values with max_linear_speed 0.35,
    and ex62_turtle.yaml itself unchanged (normal days still run at its speed)."""
    if not requirements.files_installed(verdict, package, (TURTLE_YAML, 'launch/' + DEMO_FILE,
                                                           'launch/' + TURTLE_FILE)):
        return verdict
    normal = probe(package, TURTLE_FILE, (CONTROLLER,), inspect=_read_controller)
    if not controller_started(verdict, normal, TURTLE_FILE) or \
            (from_file := parameters_read(verdict, normal)) is None:
        return verdict
    verdict.expect(
        from_file.get('max_linear_speed') != DEMO_SPEED,
        f'{TURTLE_FILE} (normal days) keeps max_linear_speed '
        f'{from_file.get("max_linear_speed")!r}',
        f'{TURTLE_FILE} now also gives max_linear_speed {DEMO_SPEED}: keep {TURTLE_YAML} '
        f'unchanged (normal days stay slow) and set {DEMO_SPEED} in {DEMO_FILE} only')
    demo = probe(package, DEMO_FILE, (CONTROLLER,), inspect=_read_controller)
    if not controller_started(verdict, demo, DEMO_FILE) or \
            (got := parameters_read(verdict, demo)) is None:
        return verdict
    speed = got.get('max_linear_speed')
    hint = (': the dictionary must come after the file in parameters=[...], '
            'the later entry wins' if speed == from_file.get('max_linear_speed') else '')
    verdict.expect(_same(speed, DEMO_SPEED), f'{CONTROLLER} has max_linear_speed {DEMO_SPEED}',
                   f'{CONTROLLER} got max_linear_speed {_shown(speed)}, expected {DEMO_SPEED} '
                   f'from {DEMO_FILE}{hint}')
    expect_values(verdict, got, {k: v for k, v in from_file.items()
                                 if k in DEFAULTS and k != 'max_linear_speed'},
                  f'{TURTLE_YAML}, as {TURTLE_FILE} gives it (load the file in the demo too)')
    return verdict


def check_scout_5hz(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Scout's values from robot_params.yaml, with the control loop started at 5 Hz."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, SCOUT_FILE, (CONTROLLER,), inspect=_read_controller)
    if not controller_started(verdict, run, SCOUT_FILE) or \
            (got := parameters_read(verdict, run)) is None:
        return verdict
    scout = flat(yaml.safe_load(ROBOT_PARAMS.read_text())['robot_controller']['ros__parameters'])
    rate = got.get('update_rate')
    hint = ('' if rate != scout['update_rate'] else
            ': give update_rate 5.0 after robot_params.yaml in parameters=[...], '
            'the later entry wins')
    verdict.expect(_same(rate, SCOUT_RATE), f'{CONTROLLER} has update_rate {SCOUT_RATE}',
                   f'{CONTROLLER} got update_rate {_shown(rate)}, expected {SCOUT_RATE} '
                   f'from {SCOUT_FILE}{hint}')
    started = started_rate(run)
    if started is None:
        verdict.fail(f'{CONTROLLER} logged no "starting with update_rate=..." line: give its '
                     "Node action output='screen' so that the check can read its start-up log")
    else:
        verdict.expect(
            float(started) == SCOUT_RATE,
            f'{CONTROLLER} started its control loop at {started} Hz (its start-up log line)',
            f'{CONTROLLER} started its control loop at {started} Hz (its log: "starting with '
            f'update_rate={started} Hz"): it reads update_rate once, when it starts, so a '
            f'value set after the start (ros2 param set) changes nothing; give {SCOUT_RATE} '
            "in the Node's parameters")
    expect_values(verdict, got, {k: v for k, v in scout.items() if k != 'update_rate'},
                  'robot_params.yaml (load it from my_robot_pkg)')
    return verdict


EXERCISES = (
    Exercise('ex62_turtle', 'Exercise 6.2.1 (a parameter file for turtle)',
             (TURTLE_YAML, 'launch/' + TURTLE_FILE), check_turtle),
    Exercise('ex62_turtle_demo', 'Exercise 6.2.2 (demo day)',
             ('launch/' + DEMO_FILE,), check_turtle_demo),
    Exercise('ex62_scout_5hz', 'Exercise 6.2.3 (scout at 5 Hz)',
             ('launch/' + SCOUT_FILE,), check_scout_5hz),
)
