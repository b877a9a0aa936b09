"""Checks of lesson 7.2 (Building the bringup).

Exercise 7.2.1: the student's own top level for the capstone, with a
`robots` argument (a comma-separated list of turtle names) instead of a
count.  The check launches it as their terminal would, with the default
list and with `robots:=turtle1,turtle3`, and judges the running system:
exactly the robots named, each with its six nodes in its namespace, each
on its own route (the `waypoints` of config/<robot>.yaml: an argument that
leaks from one robot's include into the next shows there), and each named
turtle in the world.  Never the file's text, so any valid way passes.
"""
from __future__ import annotations

import re
import time
from typing import Any

import yaml

from labkit.errors import LabkitError
from labkit.grading import capstone, requirements
from labkit.grading.capstone import ROBOT_NODES, SIMULATOR
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, graph, read_parameters

FILE = 'ex72_my_capstone.launch.py'
#: the arguments each run gets, and the robots it must start
CASES = (({}, ('turtle1', 'turtle2')),
         ({'robots': 'turtle1,turtle3'}, ('turtle1', 'turtle3')))
#: a spawner asks turtlesim for its turtle after both started; bounds the wait for that
SPAWN_GUARD = 30.0
LAUNCH_GUARD = 60.0  # seconds; only stops a broken answer from hanging the check
ROBOT_NAMESPACE = re.compile(r'^/(turtle\d+)/')


def route_of(robot: str) -> list[float]:
    """The waypoints config/<robot>.yaml gives the robot's patrol planner."""
    sections = yaml.safe_load((capstone.CONFIG / f'{robot}.yaml').read_text())
    planner = sections['/**/patrol_planner']['ros__parameters']
    return [float(value) for value in planner['waypoints']]


def _spawned(robots: tuple[str, ...]) -> set[str]:
    """The named turtles whose pose turtlesim publishes, waiting (bounded) for the spawners."""
    deadline = time.monotonic() + SPAWN_GUARD
    while True:
        snapshot = graph()
        found = {robot for robot in robots if f'/{robot}/pose' in snapshot.topics
                 and SIMULATOR in snapshot.publishers(f'/{robot}/pose')}
        if found == set(robots) or time.monotonic() > deadline:
            return found
        time.sleep(0.5)


def _inspect(robots: tuple[str, ...]):
    """What the check reads while the launch is up: turtles spawned, each robot's route."""
    def inspect(snapshot: GraphSnapshot) -> dict[str, Any]:
        routes: dict[str, list[float] | None] = {}
        for robot in robots:
            planner = f'/{robot}/patrol_planner'
            try:
                routes[robot] = [float(v) for v in read_parameters(planner)['waypoints']] \
                    if planner in snapshot.nodes else None
            except (LabkitError, KeyError):
                routes[robot] = None
        return {'spawned': _spawned(robots), 'routes': routes}
    return inspect


def _list_not_split(run: LaunchProbe, robots: tuple[str, ...]) -> bool:
    """The whole list shows up as one name in the launch's output: a namespace
    (`/turtle1,turtle3/...`) or a parameter file (`turtle1,turtle3.yaml`); not the
    argument itself, which rcl repeats in a warning."""
    name = re.compile(rf'/{re.escape(",".join(robots))}(/|\.yaml)')
    return any(name.search(line) for line in run.lines)


def _robots_running(verdict: Verdict, run: LaunchProbe, robots: tuple[str, ...]) -> None:
    for robot in robots:
        for node in ROBOT_NODES:
            requirements.node_running(
                verdict, run, f'/{robot}/{node}',
                f"include capstone_bringup's robot.launch.py once for every name in the "
                f'list, with robot:={robot}')
    extra = sorted({match.group(1) for node in run.nodes
                    if (match := ROBOT_NAMESPACE.match(node))} - set(robots))
    verdict.expect(not extra, f'no robot runs that the list does not name ({", ".join(robots)})',
                   f'{", ".join(extra)} runs, but the list names only {", ".join(robots)}: '
                   'start one robot per name in robots, not a fixed count')


def _turtles_in_the_world(verdict: Verdict, run: LaunchProbe, robots: tuple[str, ...]) -> None:
    spawned = (run.inspected or {}).get('spawned', set())
    for robot in robots:
        verdict.expect(robot in spawned, f'{robot} is in the world ({SIMULATOR} publishes '
                       f'/{robot}/pose)',
                       f'{robot} is not in the world ({SIMULATOR} publishes no /{robot}/pose): '
                       "include sim.launch.py once, with robot_count the highest turtle "
                       f"number in the list ({robot} -> '{robot.removeprefix('turtle')}')")


def _own_routes(verdict: Verdict, run: LaunchProbe, robots: tuple[str, ...]) -> None:
    routes = (run.inspected or {}).get('routes', {})
    for robot in robots:
        got, expected = routes.get(robot), route_of(robot)
        if got is None:
            continue  # its planner is not running: said above
        owner = next((other for other in robots if other != robot and got == route_of(other)),
                     None)
        why = (f"that is {owner}'s route: robot_params, which robot.launch.py sets from the "
               f'first robot, leaked into the next include; put each include in a '
               'GroupAction(scoped=True) of its own' if owner else
               f'give robot.launch.py robot:={robot} and let it pick config/{robot}.yaml')
        verdict.expect(got == expected,
                       f'/{robot}/patrol_planner patrols its own route, from config/{robot}.yaml',
                       f'/{robot}/patrol_planner patrols {got}, expected {expected} from '
                       f'config/{robot}.yaml: {why}')


def check_my_capstone(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Exactly the robots named, each in its namespace, on its own route, its turtle spawned."""
    if not requirements.files_installed(verdict, package):
        return verdict
    for arguments, robots in CASES:
        expected = (SIMULATOR, *capstone.robot_nodes(*robots))
        run = probe(package, FILE, expected, arguments=arguments, timeout=LAUNCH_GUARD,
                    inspect=_inspect(robots))
        if _list_not_split(run, robots):
            verdict.fail(f"`{run.command}` gave robot.launch.py the whole list "
                         f"'{','.join(robots)}' as one robot name: split the list at the "
                         'commas and include robot.launch.py once per name')
            return verdict
        if not requirements.launch_ran(verdict, run):
            return verdict
        requirements.node_running(verdict, run, SIMULATOR,
                                  "include capstone_bringup's sim.launch.py once")
        _robots_running(verdict, run, robots)
        _turtles_in_the_world(verdict, run, robots)
        _own_routes(verdict, run, robots)
    return verdict


EXERCISES = (
    Exercise('ex72_my_capstone', 'Exercise 7.2.1 (your own top level, with a list of robots)',
             ('launch/' + FILE,), check_my_capstone),
)
