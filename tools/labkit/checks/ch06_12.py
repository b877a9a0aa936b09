"""Checks of lesson 6.12 (Architecture patterns).

The student composes a fleet from robot_bringup's robot.launch.py: as many
scouts as the argument robot_count asks for, one namespace each.  The check
launches their file as a terminal would, with the default count and with
another one, and judges the running graph: which scouts run, each scout's
wiring inside its own namespace, and the parameters that prove the
arguments reached each include.  Never the file's text.
"""
from __future__ import annotations

from labkit.checks.ch06_03 import parameter_is, parameters_of
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

FLEET_FILE = 'ex612_fleet.launch.py'
ROBOT_FILE = "robot_bringup's launch/robot.launch.py"
PREFIX = 'scout'
SENSOR_RATE = 5.0
#: The runs judged: (arguments given, scouts expected).
RUNS = (({}, 2), ({'robot_count': '3'}, 3))
PIPELINE = ('sensor_publisher', 'data_processor', 'robot_controller')
LOOP_TOO_EARLY = "not 'LaunchConfiguration'"
MISSING_NAME = "missing required argument 'robot_name'"


def _scout_nodes(number: int) -> tuple[str, ...]:
    return tuple(f'/{PREFIX}{number}/{node}' for node in PIPELINE)


def _launch_failed(verdict: Verdict, run: LaunchProbe) -> bool:
    """The launch stopped with an error: say what it means for a fleet file."""
    text = '\n'.join(run.lines)
    if LOOP_TOO_EARLY in text:
        return verdict.fail(
            f'`{run.command}` stopped before any scout started: int() got a '
            'LaunchConfiguration. generate_launch_description() runs before the launch has '
            "any argument's value; read robot_count inside an OpaqueFunction, with "
            "LaunchConfiguration('robot_count').perform(context), and loop there").passed
    if MISSING_NAME in text:
        return verdict.fail(
            f'`{run.command}` stopped: {MISSING_NAME}. {ROBOT_FILE} declares robot_name '
            "without a default because it is the robot's namespace: pass 'robot_name': "
            f"f'{PREFIX}{{number}}' in every include's launch_arguments").passed
    return requirements.launch_ran(verdict, run)


def _scouts_running(verdict: Verdict, run: LaunchProbe, count: int, given: str) -> bool:
    shared = sorted(node for node, owners in run.node_processes.items() if len(owners) > 1)
    if shared:
        return verdict.fail(f'the scouts share one namespace{given} (nodes: '
                            f'{", ".join(run.nodes)}): give each include its own robot_name, '
                            f"f'{PREFIX}{{number}}', which is the robot's namespace").passed
    hint = (f'start {count} scouts{given}: include {ROBOT_FILE} once per scout, with '
            f'robot_name {PREFIX}1 ... {PREFIX}{count}; the count must come from the '
            'argument robot_count, not from a number written in your file')
    ok = True
    for number in range(1, count + 1):
        for node in _scout_nodes(number):
            ok = requirements.node_running(verdict, run, node, hint) and ok
    expected = {node for number in range(1, count + 1) for node in _scout_nodes(number)}
    extra = sorted(set(run.nodes) - expected)
    if extra:
        ok = verdict.fail(f'{", ".join(extra)} also run{given}: start exactly {count} scouts, '
                          'one per count, and nothing else').passed and ok
    return ok


def _scouts_wired(verdict: Verdict, run: LaunchProbe, count: int) -> None:
    for number in range(1, count + 1):
        sensor, processor, controller = _scout_nodes(number)
        requirements.topic_link(verdict, run, f'/{PREFIX}{number}/distance', sensor, processor)
        requirements.topic_link(verdict, run, f'/{PREFIX}{number}/distance_filtered',
                                processor, controller)


def _arguments_passed_down(verdict: Verdict, run: LaunchProbe, count: int) -> None:
    for number in range(1, count + 1):
        sensor, _, controller = _scout_nodes(number)
        parameter_is(verdict, run, sensor, 'publish_rate', SENSOR_RATE,
                     'from sensor_rate passed down',
                     f"pass 'sensor_rate': '{SENSOR_RATE}' in the include's launch_arguments "
                     f'as well; an argument not passed keeps the default of {ROBOT_FILE}, '
                     'without a warning')
        parameter_is(verdict, run, controller, 'robot_name', f'{PREFIX}{number}',
                     'from robot_name passed down',
                     f"pass 'robot_name': '{PREFIX}{number}' to this scout's include")


def _judge_run(verdict: Verdict, package: StudentPackage, arguments: dict[str, str],
               count: int) -> bool:
    given = ' with ' + ' '.join(f'{k}:={v}' for k, v in arguments.items()) if arguments \
        else ' with the defaults'
    nodes = tuple(node for number in range(1, count + 1) for node in _scout_nodes(number))
    inspected = tuple(node for node in nodes if not node.endswith('/data_processor'))
    run = probe(package, FLEET_FILE, nodes, arguments=arguments,
                inspect=parameters_of(inspected))
    if not _launch_failed(verdict, run):
        return False
    if _scouts_running(verdict, run, count, given):
        _scouts_wired(verdict, run, count)
        _arguments_passed_down(verdict, run, count)
    return requirements.names_unique(verdict, run)


def check_fleet(package: StudentPackage, verdict: Verdict) -> Verdict:
    """robot_count scouts, each robot.launch.py in its own namespace, arguments passed down."""
    if not requirements.files_installed(verdict, package):
        return verdict
    for arguments, count in RUNS:
        if not _judge_run(verdict, package, arguments, count):
            break
    return verdict


EXERCISES = (
    Exercise('ex612_fleet', 'Exercise 6.12.1 (a fleet of scouts from one argument)',
             ('launch/' + FLEET_FILE,), check_fleet),
)
