"""Checks of lesson 6.13 (Configuration management).

The student layers a site file of their own (the warehouse) over the rover
configuration of the book's package `rover_config` (package defaults, then
the robot's file).  The check launches the student's launch file for two
robots, `robot:=scout` (the default) and `robot:=ranger`, and reads back
what the running nodes got: the warehouse's values must have won, and the
robot's and the defaults' values the warehouse does not set must still be
there.  A value that did not apply is named with the layer it came from, so
a silently ignored section is told apart from a file loaded too early.
"""
from __future__ import annotations

from typing import Any

from labkit.checks.ch06_00 import EXCEPTION
from labkit.checks.ch06_03 import parameter_is, parameters_of
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

LAUNCH_FILE = 'ex613_rover.launch.py'
SITE_FILE = 'config/ex613_warehouse.yaml'
#: What the warehouse sets: (node, parameter) -> value.
WAREHOUSE = {('sensor_publisher', 'publish_rate'): 5.0,
             ('robot_controller', 'max_linear_speed'): 0.4}
#: What rover_config's robot files set and the warehouse leaves alone, per robot.
ROBOTS: dict[str, dict[tuple[str, str], Any]] = {
    'scout': {('robot_controller', 'update_rate'): 20.0, ('data_processor', 'window_size'): 5},
    'ranger': {('robot_controller', 'update_rate'): 15.0, ('data_processor', 'window_size'): 8},
}
NODES = ('sensor_publisher', 'data_processor', 'robot_controller')


def _crashed(verdict: Verdict, run: LaunchProbe) -> bool:
    """A node stopped while it started: a parameter file it could not read or use."""
    errors = [f"{m['process']}: {m['message']}" for line in run.lines
              if (m := EXCEPTION.match(line))]
    if not errors:
        return False
    hint = ''
    if any('ros__parameters' in error for error in errors):
        hint = (f' In {SITE_FILE}, the parameters of each key go under ros__parameters: '
                '(two underscores), as in every parameter file.')
    elif any('expecting type' in error for error in errors):
        hint = (' YAML decides the type by how a value is written: 5 is an integer, 5.0 a '
                'float; write the type the node declares.')
    verdict.fail(f'a node stopped while it started: {errors[-1]}.{hint}')
    return True


def _lost(robot: str, name: str) -> str:
    """Why a warehouse value did not reach the node, and how to see it."""
    node = f'/{robot}/robot_controller' if name == 'max_linear_speed' \
        else f'/{robot}/sensor_publisher'
    return ("that is the value of rover_config's defaults.yaml or "
            f"config/robots/{robot}.yaml, so your file's section did not apply "
            f'(ros2 param dump {node} shows what the node got). '
            f"Your file must come after the robot's file in parameters=[...], and each "
            "section must be keyed the way rover_config's layers are, /**/<node name>: a key "
            'that names no node is ignored, one that names only one robot misses the others, '
            'and a /** section is applied before the /**/<node> ones, however late its file '
            'comes, because SetParameter already put /** first')


def _judge(verdict: Verdict, package: StudentPackage, robot: str, arguments: dict[str, str]
           ) -> bool:
    given = f'robot:={robot}' if arguments else f'the defaults (robot {robot})'
    nodes = tuple(f'/{robot}/{node}' for node in NODES)
    run = probe(package, LAUNCH_FILE, nodes, arguments=arguments, inspect=parameters_of(nodes))
    if _crashed(verdict, run) or not requirements.launch_ran(verdict, run):
        return False
    if not all([requirements.node_running(verdict, run, node,
                                          f'{LAUNCH_FILE} must start it in the namespace '
                                          f'/{robot} with {given}') for node in nodes]):
        return False
    for (node, name), value in WAREHOUSE.items():
        parameter_is(verdict, run, f'/{robot}/{node}', name, value,
                     f'from {SITE_FILE} with {given}', _lost(robot, name))
    for (node, name), value in ROBOTS[robot].items():
        parameter_is(verdict, run, f'/{robot}/{node}', name, value,
                     f"from rover_config's layers with {given}",
                     f"keep rover_config's defaults.yaml and config/robots/<robot>.yaml as "
                     f"the first layers, and set only the warehouse's values in {SITE_FILE}")
    parameter_is(verdict, run, f'/{robot}/robot_controller', 'robot_name', robot,
                 f"from rover_config's defaults.yaml ($(var robot)) with {given}",
                 "load rover_config's defaults.yaml with ParameterFile(..., allow_substs=True)")
    return True


def check_warehouse(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The warehouse's values win over the robot's, for scout and for ranger."""
    if not requirements.files_installed(verdict, package):
        return verdict
    if _judge(verdict, package, 'scout', {}):
        _judge(verdict, package, 'ranger', {'robot': 'ranger'})
    return verdict


EXERCISES = (
    Exercise('ex613_warehouse', 'Exercise 6.13.1 (a site layer that wins)',
             (SITE_FILE, 'launch/' + LAUNCH_FILE), check_warehouse),
)
