"""Checks of lesson 6.3 (Launch arguments and substitutions).

They start the student's launch file the way a terminal would, with the
defaults and with arguments on the command line, and judge what `--show-args`
lists, the parameters the nodes got, which nodes run and the launch log;
never the text of the file.
"""
from __future__ import annotations

import re
import subprocess
from dataclasses import dataclass
from typing import Any

from labkit.errors import LabkitError
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, read_parameters
from labkit.ros2_command import find_ros2

ROVER_FILE = 'ex63_rover.launch.py'
SCOPED_FILE = 'ex63_bringup_scoped.launch.py'
CONTROLLER = '/robot_controller'
SENSOR = '/sensor_publisher'
FAST_LINE = 'Fast robot: max_speed {} m/s is above 1.0 m/s'
ROBOTS = ('/robot1/robot_controller', '/robot2/robot_controller')
#: `ros2 launch --show-args` never starts anything; this only stops a hang.
SHOW_ARGS_TIMEOUT = 60
ARGUMENT_HEADER = re.compile(r"^    '(?P<name>[^']+)':$")
DEFAULT_LINE = re.compile(r'^        \(default: (?P<value>.*)\)$')
NO_DESCRIPTION = ('no description given', 'One of: ')


@dataclass(frozen=True)
class ShownArgument:
    """One argument as `ros2 launch ... --show-args` lists it."""

    description: str
    default: str | None  # None: required (no default)


def _unquoted(text: str) -> str:
    """'0.3' -> 0.3; a substitution's description (no quotes) stays as it is."""
    return text[1:-1] if len(text) >= 2 and text[0] == text[-1] == "'" else text


def show_args(package: StudentPackage, launch_file: str) -> tuple[dict[str, ShownArgument], str]:
    """The arguments `ros2 launch <package> <file> --show-args` lists, and its output."""
    env = package.environment()
    result = subprocess.run([find_ros2(env), 'launch', package.name, launch_file, '--show-args'],
                            env=env, cwd=package.workspace, capture_output=True, text=True,
                            timeout=SHOW_ARGS_TIMEOUT)
    blocks: dict[str, list[str]] = {}
    current: list[str] | None = None
    for line in result.stdout.splitlines():
        if header := ARGUMENT_HEADER.match(line):
            current = blocks.setdefault(header['name'], [])
        elif current is not None and line.strip():
            current.append(line)
    shown = {}
    for name, lines in blocks.items():
        defaults = [_unquoted(m['value']) for line in lines
                    if (m := DEFAULT_LINE.match(line))]
        text = ' '.join(line.strip() for line in lines if not DEFAULT_LINE.match(line))
        shown[name] = ShownArgument(text, defaults[0] if defaults else None)
    return shown, (result.stdout + result.stderr).strip()


def parameters_of(nodes: tuple[str, ...]) -> Any:
    """An `inspect` for probe(): these nodes' parameters (None for a node that does not answer)."""
    def inspect(snapshot: GraphSnapshot) -> dict[str, dict[str, Any] | None]:
        found: dict[str, dict[str, Any] | None] = {}
        for node in nodes:
            try:
                found[node] = read_parameters(node) if node in snapshot.nodes else None
            except LabkitError:
                found[node] = None
        return found
    return inspect


def _shown_value(value: Any) -> str:
    return repr(value) if isinstance(value, str) else str(value)


def parameter_is(verdict: Verdict, run: LaunchProbe, node: str, name: str, expected: Any,
                 source: str, fix: str) -> bool:
    """`node` got `expected` for parameter `name`; `source` says where that value comes from."""
    got = (run.inspected or {}).get(node)
    if got is None:
        return verdict.expect(False, '', f'{node} did not answer, so its {name} could not be '
                                         'read: it must run until the launch is stopped')
    value = got.get(name)
    if isinstance(expected, float) and isinstance(value, (int, float)) \
            and not isinstance(value, bool):
        met = abs(value - expected) < 1e-9
    else:
        met = value == expected
    return verdict.expect(
        met, f'{node} got {name} {_shown_value(expected)} {source}',
        f'{node} got {name} {_shown_value(value)}, expected {_shown_value(expected)} '
        f'{source}: {fix}')


def _user_lines(run: LaunchProbe) -> list[str]:
    return [line.split(']: ', 1)[1] for line in run.lines
            if line.startswith('[INFO] [launch.user]: ')]


def _arguments_listed(verdict: Verdict, package: StudentPackage) -> None:
    shown, output = show_args(package, ROVER_FILE)
    command = f'ros2 launch {package.name} {ROVER_FILE} --show-args'
    if not shown:
        verdict.fail(f'`{command}` lists no arguments; it printed:\n      '
                     + '\n      '.join(output.splitlines()[-5:] or ['nothing']))
        return
    for name, default in (('robot_name', 'rover'), ('max_speed', '0.3'), ('use_sensor', 'true')):
        argument = shown.get(name)
        if argument is None:
            verdict.fail(f'`{command}` does not list {name!r} (it lists '
                         f'{", ".join(map(repr, shown))}): declare it with '
                         f"DeclareLaunchArgument('{name}', default_value='{default}', ...) and "
                         'put it in the returned LaunchDescription')
            continue
        verdict.expect(argument.default == default,
                       f'--show-args lists {name!r} with the default {default!r}',
                       f'--show-args lists {name!r} with ' + (
                           f'the default {argument.default!r}' if argument.default is not None
                           else 'no default (so it is required)')
                       + f", expected default_value='{default}'")
        if name != 'use_sensor':
            verdict.expect(not argument.description.startswith(NO_DESCRIPTION),
                           f'{name!r} has a description ({argument.description!r})',
                           f'{name!r} has no description in --show-args: add '
                           "description='...' to its DeclareLaunchArgument")


def _defaults(verdict: Verdict, package: StudentPackage) -> bool:
    run = probe(package, ROVER_FILE, (CONTROLLER, SENSOR), inspect=parameters_of((CONTROLLER,)))
    if not requirements.launch_ran(verdict, run):
        return False
    source = 'with the defaults'
    if requirements.node_running(verdict, run, CONTROLLER,
                                 "start it with Node(package='my_robot_pkg', "
                                 "executable='robot_controller', ...)"):
        parameter_is(verdict, run, CONTROLLER, 'robot_name', 'rover', source,
                     "set the parameter robot_name from LaunchConfiguration('robot_name'), "
                     "whose default_value is 'rover'")
        parameter_is(verdict, run, CONTROLLER, 'max_linear_speed', 0.3, source,
                     "set the parameter max_linear_speed (the controller's name for it) from "
                     "LaunchConfiguration('max_speed'), whose default_value is '0.3'")
    requirements.node_running(verdict, run, SENSOR, 'with use_sensor at its default, true, '
                              "start Node(package='my_robot_pkg', executable='sensor_publisher')")
    fast = [line for line in _user_lines(run) if line.startswith('Fast robot')]
    verdict.expect(not fast, 'no fast-robot line with the default max_speed 0.3',
                   f'{fast[0]!r} was logged with max_speed 0.3 (the default): give the LogInfo '
                   "condition=IfCondition(PythonExpression([max_speed, ' > 1.0']))"
                   if fast else '')
    return True


def _overrides(verdict: Verdict, package: StudentPackage) -> None:
    arguments = {'robot_name': 'explorer', 'max_speed': '1.5', 'use_sensor': 'false'}
    given = ' '.join(f'{name}:={value}' for name, value in arguments.items())
    run = probe(package, ROVER_FILE, (CONTROLLER,), arguments=arguments,
                inspect=parameters_of((CONTROLLER,)))
    if not requirements.launch_ran(verdict, run):
        return
    source = 'from the command line'
    if requirements.node_running(verdict, run, CONTROLLER, f'it must start with {given} too'):
        parameter_is(verdict, run, CONTROLLER, 'robot_name', 'explorer', source,
                     "pass LaunchConfiguration('robot_name'), not a fixed text, as the "
                     'parameter robot_name')
        parameter_is(verdict, run, CONTROLLER, 'max_linear_speed', 1.5, source,
                     "pass LaunchConfiguration('max_speed') as the parameter max_linear_speed")
    verdict.expect(SENSOR not in run.nodes, 'use_sensor:=false leaves /sensor_publisher out',
                   f'{SENSOR} is running although use_sensor:=false: give its Node action '
                   "condition=IfCondition(LaunchConfiguration('use_sensor'))")
    line = FAST_LINE.format('1.5')
    verdict.expect(line in _user_lines(run), f'max_speed:=1.5 logs {line!r}',
                   f'with max_speed:=1.5 the launch log has no line {line!r} '
                   f'(its LogInfo lines: {_user_lines(run) or "none"}): add a LogInfo with that '
                   "message, condition=IfCondition(PythonExpression([max_speed, ' > 1.0']))")


def _invalid_choice_refused(verdict: Verdict, package: StudentPackage) -> None:
    run = probe(package, ROVER_FILE, arguments={'use_sensor': 'yes'})
    refusal = 'Argument "use_sensor" provided value "yes" is not valid'
    refused = run.exited_by_itself and not run.processes \
        and any(refusal in line for line in run.launch_errors())
    if refused:
        verdict.expect(True, 'use_sensor:=yes is refused before anything starts '
                             '(only true or false are accepted)', '')
        return
    what = (f'it started {", ".join(run.processes)}' if run.processes else 'it started nothing')
    errors = run.launch_errors()
    verdict.expect(False, '', f'use_sensor:=yes was not refused as an invalid choice ({what}'
                   + (f', then stopped with: {errors[-1]}' if errors else '')
                   + "): give DeclareLaunchArgument('use_sensor', ...) "
                     "choices=['true', 'false']")


def check_rover(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Three arguments with defaults, used by the nodes, a condition and a refused choice."""
    if not requirements.files_installed(verdict, package):
        return verdict
    _arguments_listed(verdict, package)
    if _defaults(verdict, package):
        _overrides(verdict, package)
        _invalid_choice_refused(verdict, package)
    return verdict


def _robot_names(verdict: Verdict, run: LaunchProbe, second: str, source: str,
                 fix: str) -> None:
    for node in ROBOTS:
        requirements.node_running(verdict, run, node, 'include robot_instance.launch.py of '
                                  f"my_robot_pkg with robot_ns:={node.split('/')[1]}")
    if ROBOTS[0] in run.nodes:
        parameter_is(verdict, run, ROBOTS[0], 'robot_name', 'alpha', 'from its include',
                     "give the first include launch_arguments robot_ns: 'robot1', "
                     "robot_name: 'alpha'")
    if ROBOTS[1] in run.nodes:
        parameter_is(verdict, run, ROBOTS[1], 'robot_name', second, source, fix)


def check_bringup_scoped(package: StudentPackage, verdict: Verdict) -> Verdict:
    """robot1 is alpha, robot2 keeps the default (or the command line's) robot_name."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, SCOPED_FILE, ROBOTS, inspect=parameters_of(ROBOTS))
    if not requirements.launch_ran(verdict, run):
        return verdict
    _robot_names(verdict, run, 'scout', '(the default of robot_instance.launch.py)',
                 "the first include's robot_name:=alpha is still set when the second include "
                 'runs; put the first include in its own GroupAction([...]) so it is forgotten')
    order = [line.rsplit('/', 1)[-1] for line in _user_lines(run)
             if line.startswith('Starting controller of ')]
    verdict.expect(order[:2] == ['robot1', 'robot2'], 'robot1 is included before robot2',
                   f'the includes ran in the order {", ".join(order) or "(none logged)"}: '
                   'robot1 must be included first, as in bringup_twice.launch.py; '
                   'scope it instead of moving it')
    requirements.names_unique(verdict, run)
    given = probe(package, SCOPED_FILE, ROBOTS, arguments={'robot_name': 'bravo'},
                  inspect=parameters_of(ROBOTS))
    if not requirements.launch_ran(verdict, given):
        return verdict
    leaked = ((given.inspected or {}).get(ROBOTS[1]) or {}).get('robot_name') == 'alpha'
    parameter_is(verdict, given, ROBOTS[1], 'robot_name', 'bravo',
                 'from robot_name:=bravo on the command line',
                 "robot1's robot_name:=alpha is still set when the second include runs; put "
                 'the first include in its own GroupAction([...])' if leaked else
                 'the second include must not set robot_name itself (no robot_name in its '
                 'launch_arguments), so that it keeps what whoever starts the launch gives; '
                 'scope the first include with GroupAction instead')
    parameter_is(verdict, given, ROBOTS[0], 'robot_name', 'alpha',
                 'from its include, even with robot_name:=bravo on the command line',
                 "the first include's own robot_name: 'alpha' must win over the command line")
    return verdict


EXERCISES = (
    Exercise('ex63_rover', 'Exercise 6.3.1 (a rover with three knobs)',
             ('launch/' + ROVER_FILE,), check_rover),
    Exercise('ex63_bringup_scoped', 'Exercise 6.3.2 (two robots, each with its own name)',
             ('launch/' + SCOPED_FILE,), check_bringup_scoped),
)
