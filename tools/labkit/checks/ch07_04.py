"""Checks of the capstone project brief (chapter 7): the night shift.

The student's own bringup, `night_shift.launch.py`, reuses the capstone's
sim.launch.py and robot.launch.py for three robots, turtle3 the inspector
with a site layer of its own, and an argument `shift` that selects a
parameter layer.  The check grades the running system, as a terminal would
start it: one launch for the day shift and one for the night shift (each
reads the nine values that make each robot itself while the launch is up,
and the day shift is also checked against the student's spec with
`speccheck live`: it must pass), one with a shift that does not exist (it
must be refused, naming the allowed values), then the spec against the
capstone with three ordinary robots (it must fail: turtle3 is no inspector
there).  Each system is started once: the capstone's 19 processes take most
of the check's time on a loaded machine.
"""
from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import yaml

from labkit.errors import LabkitError
from labkit.grading import capstone, requirements, spec_run
from labkit.grading.capstone import ROBOT_NODES, SIMULATOR
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, read_parameters

LAUNCH_FILE = 'night_shift.launch.py'
SPEC = 'specs/night_shift.spec.yaml'
LAYERS = ('config/night_shift_inspector.yaml', 'config/night_shift_day.yaml',
          'config/night_shift_night.yaml')
ROBOTS = ('turtle1', 'turtle2', 'turtle3')
INSPECTOR = 'turtle3'
EXPECTED_NODES = (SIMULATOR, *capstone.robot_nodes(*ROBOTS))
BAD_SHIFT = 'evening'
#: Seconds; only stops a launch that never comes up (three robots on a loaded machine).
STARTUP_GUARD = 60.0
SHOWN_FINDINGS = 4
#: The planted defect: the capstone with three ordinary robots (turtle3 no inspector).
DEFECT = ('capstone_bringup', 'capstone.launch.py', 'robot_count:=3')
DEFECT_SHOWN = 'capstone.launch.py robot_count:=3'


@dataclass(frozen=True)
class Value:
    """One parameter a robot must have, and where the brief says it comes from."""

    node: str  # in the robot's namespace
    name: str
    value: Any
    source: str


#: What the brief's site layer (N2) makes of the inspector.
INSPECTOR_VALUES = {'waypoints': [9.0, 8.0, 2.5, 8.0, 2.5, 3.0, 9.0, 3.0],
                    'max_linear': 0.6, 'stop_distance': 1.2}


def capstone_value(robot: str, node: str, name: str) -> Any:
    """A robot's parameter as the capstone configures it: config/defaults.yaml, then
    config/<robot>.yaml over it (robot.launch.py's two layers)."""
    value = None
    for layer in ('defaults.yaml', f'{robot}.yaml'):
        sections = yaml.safe_load((capstone.CONFIG / layer).read_text()) or {}
        value = sections.get(f'/**/{node}', {}).get('ros__parameters', {}).get(name, value)
    return value


def day_value(robot: str, node: str, name: str) -> Any:
    """The brief's day-shift value: the inspector's layer for turtle3, else the capstone's."""
    return INSPECTOR_VALUES[name] if robot == INSPECTOR else capstone_value(robot, node, name)


def expected(robot: str, shift: str) -> tuple[Value, ...]:
    """What N2-N4 fix for `robot` in `shift`."""
    own = ("the inspector's site layer (N2)" if robot == INSPECTOR
           else f"the capstone's config of {robot} (N3)")
    day_speed = day_value(robot, 'controller', 'max_linear')
    speed = day_speed if shift == 'day' else day_speed / 2
    speed_source = own if shift == 'day' else f'the night layer: half of {day_speed} (N4)'
    return (Value('patrol_planner', 'waypoints', day_value(robot, 'patrol_planner', 'waypoints'),
                  own),
            Value('controller', 'max_linear', speed, speed_source),
            Value('safety_monitor', 'stop_distance',
                  day_value(robot, 'safety_monitor', 'stop_distance'), own))


#: The nodes `expected` gives values to.  Named here, not derived from `expected`: that
#: reads the capstone's config, which a labkit installed outside the repository only
#: finds once the snippets are in the workspace (as the check runs, not at import).
VALUE_NODES = ('patrol_planner', 'controller', 'safety_monitor')
PARAMETER_NODES = tuple(sorted(f'/{robot}/{node}' for robot in ROBOTS for node in VALUE_NODES))


def read_values(snapshot: GraphSnapshot) -> dict[str, dict[str, Any] | str]:
    """The parameters of the nodes the brief gives values to, or why they could not be read."""
    found: dict[str, dict[str, Any] | str] = {}
    for node in PARAMETER_NODES:
        if node not in snapshot.nodes:
            found[node] = 'not running'
            continue
        try:
            found[node] = read_parameters(node)
        except LabkitError as error:
            found[node] = str(error)
    return found


def _same(got: Any, want: Any) -> bool:
    if isinstance(want, list):
        return isinstance(got, list) and len(got) == len(want) \
            and all(_same(g, w) for g, w in zip(got, want, strict=True))
    return isinstance(got, float) and math.isclose(got, want, abs_tol=1e-9)


@dataclass(frozen=True)
class Shift:
    """What the check takes from one shift's launch while it is up."""

    values: dict[str, dict[str, Any] | str]  # read_values
    #: the student's spec against it (the day shift, once its nodes all run), else None
    spec: spec_run.SpecRun | None = None


def _robot_values(verdict: Verdict, run: LaunchProbe, robot: str, shift: str) -> None:
    """One requirement per robot and shift: every value of `expected` as the brief says."""
    read = run.inspected.values if isinstance(run.inspected, Shift) else {}
    wrong = []
    for value in expected(robot, shift):
        node = f'/{robot}/{value.node}'
        parameters = read.get(node, 'not running')
        if isinstance(parameters, str):
            wrong.append(f'{node}: {parameters}')
        elif not _same(parameters.get(value.name), value.value):
            wrong.append(f'{node} got {value.name} {parameters.get(value.name)}, expected '
                         f'{value.value} from {value.source}')
    shown = ', '.join(f'{value.name} {value.value}' for value in expected(robot, shift))
    verdict.expect(not wrong, f'{robot} with {shown_shift(shift)}: {shown}',
                   f'{robot} with {shown_shift(shift)}: ' + '; '.join(wrong))


def _robots_running(verdict: Verdict, run: LaunchProbe) -> bool:
    ok = requirements.node_running(verdict, run, '/turtlesim',
                                   "include capstone_bringup's sim.launch.py (N1)")
    for robot in ROBOTS:
        missing = [node for node in ROBOT_NODES if f'/{robot}/{node}' not in run.nodes]
        ok = verdict.expect(
            not missing, f"{robot}'s six nodes run in /{robot}",
            f'/{robot} lacks {", ".join(missing)}: include capstone_bringup\'s robot.launch.py '
            f'with robot:={robot}, in a scoped group of its own (N1)') and ok
    return ok


def shown_shift(shift: str) -> str:
    """The day shift is run without the argument: it must be the default (N4)."""
    return 'the default shift (day)' if shift == 'day' else f'shift:={shift}'


def _inspect(package: StudentPackage, shift: str) -> Callable[[GraphSnapshot], Shift]:
    """probe()'s `inspect` for `shift`: its values, and for the day shift the student's
    spec against the running system (no second launch of the same 19 processes)."""
    def inspect(snapshot: GraphSnapshot) -> Shift:
        values = read_values(snapshot)
        judged = shift == 'day' and (package.source / SPEC).is_file() \
            and set(EXPECTED_NODES) <= set(snapshot.nodes)  # else no verdict comes to it
        return Shift(values, _spec_against_running(package) if judged else None)
    return inspect


def _shift(package: StudentPackage, shift: str) -> LaunchProbe:
    arguments = {} if shift == 'day' else {'shift': shift}
    return probe(package, LAUNCH_FILE, EXPECTED_NODES, arguments=arguments,
                 timeout=STARTUP_GUARD, inspect=_inspect(package, shift))


def _bad_shift_refused(verdict: Verdict, package: StudentPackage) -> None:
    """Stopped at its first process, if any: that alone shows the shift was not refused."""
    run = probe(package, LAUNCH_FILE, arguments={'shift': BAD_SHIFT}, timeout=STARTUP_GUARD,
                until_first_process=True)
    errors = run.launch_errors()
    text = ' '.join(errors)
    names_choices = all(re.search(rf'\b{name}\b', text) for name in ('day', 'night'))
    if not run.exited_by_itself or run.processes:
        verdict.fail(f'`{run.command}` started processes instead of '
                     f'refusing shift:={BAD_SHIFT} (N5): declare the argument with '
                     "choices=['day', 'night']")
        return
    refusal = errors[-1] if errors else ''
    verdict.expect(run.returncode != 0 and BAD_SHIFT in text and names_choices,
                   f'shift:={BAD_SHIFT} is refused before anything starts: {refusal}',
                   f'`{run.command}` ended (exit code {run.returncode}) without an error that '
                   f"names '{BAD_SHIFT}' and the allowed values day and night (N5); it said: "
                   + (' | '.join(errors) or ' | '.join(run.lines[-3:]) or 'nothing'))


def _command(package: StudentPackage, words: list[str]) -> str:
    """`speccheck live SPEC WORDS...`, as the student types it in their workspace."""
    return ' '.join(['speccheck live', package.shown(package.source / SPEC), *words])


def _spec_against_running(package: StudentPackage) -> spec_run.SpecRun:
    """The student's spec against the system running now (the day shift's launch), as
    `speccheck live SPEC` in a second terminal checks it; speccheck waits its discovery
    grace for the nodes and endpoints the spec names, which the system already runs."""
    return spec_run.run_speccheck(package, 'live', package.source / SPEC, [],
                                  _command(package, []))


def _speccheck(package: StudentPackage, target: list[str], system: str) -> spec_run.SpecRun:
    """The student's spec against `target` (the defect, which runs the same nodes as
    their system), started by speccheck; a wait that ran out on the three robots' nodes
    is repeated longer (spec_run.run_live)."""
    return spec_run.run_live(package, package.source / SPEC, target,
                             lambda words: _command(package, words),
                             EXPECTED_NODES.__contains__, system)


def _spec_passes(verdict: Verdict, package: StudentPackage, day: LaunchProbe) -> bool:
    """The student's spec against their own system: the day shift, checked while its
    probe had it up (Shift.spec)."""
    spec = package.source / SPEC
    if not spec.is_file():
        return verdict.fail(f'{package.shown(spec)} does not exist: write your spec there '
                            '(N6)').passed
    run = day.inspected.spec if isinstance(day.inspected, Shift) else None
    if run is None:  # the day shift was not up with all its nodes: said above
        return verdict.fail(f'your spec was not run: `{day.command}` did not run all of '
                            f'{len(EXPECTED_NODES)} nodes (N1)').passed
    if run.returncode == 2:
        return verdict.fail(f'`{run.command}` could not read the spec: {run.error}').passed
    findings = run.shown_findings(SHOWN_FINDINGS)
    return verdict.expect(run.returncode == 0 and not run.failed,
                          f'your spec passes your running system ({run.summary})',
                          'your running system (the day shift) fails your spec (N6): fix the '
                          f'spec or the system. `{run.command}` reported:\n      {findings}')


def _spec_catches_defect(verdict: Verdict, package: StudentPackage) -> None:
    run = _speccheck(package, ['--launch', *DEFECT], DEFECT_SHOWN)
    if run.unjudged:
        verdict.fail(run.unjudged)
        return
    first = run.failed[0] if run.failed else run.error
    verdict.expect(run.returncode == 1 and bool(run.failed),
                   f'your spec catches {DEFECT_SHOWN}, where turtle3 is no inspector: {first}',
                   f'your spec passes {DEFECT_SHOWN}, where turtle3 is an ordinary robot '
                   "(the capstone's triangle, 1.0 m/s, stop distance 0.8): give the "
                   "inspector's waypoints, max_linear and stop_distance their values in your "
                   'spec, not only its node names (N6)')


def check_night_shift(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Day and night shift as the brief says, a bad shift refused, the student's spec sound."""
    files = ('launch/' + LAUNCH_FILE, *LAYERS)  # not SPEC: it is read from src/, not installed
    if not requirements.files_installed(verdict, package, files):
        return verdict
    day = _shift(package, 'day')
    if not requirements.launch_ran(verdict, day) or not _robots_running(verdict, day):
        return verdict
    for robot in ROBOTS:
        _robot_values(verdict, day, robot, 'day')
    night = _shift(package, 'night')
    if requirements.launch_ran(verdict, night):
        for robot in ROBOTS:
            _robot_values(verdict, night, robot, 'night')
    _bad_shift_refused(verdict, package)
    if _spec_passes(verdict, package, day):
        _spec_catches_defect(verdict, package)
    return verdict


EXERCISES = (
    Exercise('ex74_night_shift', 'Capstone project (the night shift)',
             ('launch/' + LAUNCH_FILE, *LAYERS, SPEC), check_night_shift),
)
