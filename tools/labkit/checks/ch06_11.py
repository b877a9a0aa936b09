"""Checks of lesson 6.11 (One system, three formats).

The student writes the XML twin of a Python launch file of the book
(`my_robot_pkg/launch/twin_rover.launch.py`).  A twin is judged by what it
starts, never by its text: the check runs the book's Python file and the
student's XML file the same way (`--show-args`, then the defaults, then
arguments on the command line) and compares the two running systems: the
arguments and their defaults, the nodes and their namespaces, every parameter
with its type, and the topics each node really uses (its remaps).
"""
from __future__ import annotations

from typing import Any

from labkit.checks.ch06_00 import EXCEPTION
from labkit.checks.ch06_03 import ShownArgument, show_args
from labkit.checks.ch06_05 import published_by, read_by
from labkit.errors import LabkitError
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, read_parameters

ORIGINAL_PACKAGE = 'my_robot_pkg'
ORIGINAL_FILE = 'twin_rover.launch.py'
TWIN_FILE = 'ex611_rover.launch.xml'
#: The runs compared: the defaults, then every argument given on the command line.
RUNS = ({}, {'rover_name': 'rover7', 'max_speed': '0.4'})


def _all_parameters(snapshot: GraphSnapshot) -> dict[str, dict[str, Any] | None]:
    """An `inspect` for probe(): the parameters of every node in the graph."""
    found: dict[str, dict[str, Any] | None] = {}
    for node in snapshot.nodes:
        try:
            found[node] = read_parameters(node)
        except LabkitError:
            found[node] = None
    return found


def _shown(value: Any) -> str:
    kind = {bool: 'a boolean', int: 'an integer', float: 'a float', str: 'a string'}
    return f'{value!r} ({kind.get(type(value), type(value).__name__)})'


def _arguments_match(verdict: Verdict, package: StudentPackage,
                     original: dict[str, ShownArgument]) -> bool:
    """The twin declares the same arguments with the same defaults (`--show-args`)."""
    shown, output = show_args(package, TWIN_FILE)
    command = f'ros2 launch {package.name} {TWIN_FILE} --show-args'
    if not shown:
        return verdict.fail(f'`{command}` lists no arguments; it printed:\n      '
                            + '\n      '.join(output.splitlines()[-5:] or ['nothing'])
                            + f'\n    declare the arguments of {ORIGINAL_FILE} with '
                              '<arg name="..." default="..."/>').passed
    ok = True
    for name, argument in original.items():
        mine = shown.get(name)
        if mine is None:
            ok = verdict.fail(f'`{command}` does not list {name!r} (it lists '
                              f'{", ".join(map(repr, shown))}): add '
                              f'<arg name="{name}" default="{argument.default}"/>').passed and ok
        elif mine.default is None:
            ok = verdict.fail(f'the argument {name!r} has no default, so a launch without '
                              f'arguments is refused; in {ORIGINAL_FILE} its default is '
                              f'{argument.default!r}: <arg name="{name}" '
                              f'default="{argument.default}"/>').passed and ok
        else:
            ok = verdict.expect(mine.default == argument.default,
                                f'--show-args lists {name!r} with the default {mine.default!r}, '
                                f'as {ORIGINAL_FILE} does',
                                f'--show-args lists {name!r} with the default {mine.default!r}; '
                                f'in {ORIGINAL_FILE} it is {argument.default!r}') and ok
    for name in sorted(set(shown) - set(original)):
        ok = verdict.fail(f'your file declares {name!r}, which {ORIGINAL_FILE} does not: '
                          'the twin takes the same arguments, no more').passed and ok
    return ok


def _nodes_crashed(verdict: Verdict, run: LaunchProbe) -> bool:
    """A node of the twin stopped while it started (e.g. a parameter of the wrong type)."""
    errors = [f"{m['process']}: {m['message']}" for line in run.lines
              if (m := EXCEPTION.match(line))]
    if not errors:
        return False
    hint = ''
    if any('expecting type' in error for error in errors):
        hint = (' In XML, value="5" is an integer, value="5.0" a float and value="true" a '
                'boolean, as they would be in Python; type="str" makes any value a string.')
    verdict.fail(f'a node stopped while it started: {errors[-1]}.{hint}')
    return True


def _same_nodes(verdict: Verdict, original: LaunchProbe, twin: LaunchProbe, given: str) -> bool:
    ok = True
    for node in original.nodes:
        if node in twin.nodes:
            continue
        base = node.rsplit('/', 1)[1]
        elsewhere = [mine for mine in twin.nodes if mine.rsplit('/', 1)[1] == base]
        where = node.rsplit('/', 1)[0] or '/'
        if elsewhere:
            message = (f'{given}, your {base} runs as {elsewhere[0]}; {ORIGINAL_FILE} runs it '
                       f'as {node}: put the nodes into the namespace {where} with '
                       '<push_ros_namespace namespace="$(var rover_name)"/> as the first '
                       'line of a <group> that holds them')
        else:
            message = (f'{given}, {node} is not in the graph (yours: '
                       f'{", ".join(twin.nodes) or "none"}): {ORIGINAL_FILE} starts it')
        ok = verdict.fail(message).passed and ok
    for node in sorted(set(twin.nodes) - set(original.nodes)):
        if not any(node.rsplit('/', 1)[1] == mine.rsplit('/', 1)[1] for mine in original.nodes):
            ok = verdict.fail(f'{given}, your file starts {node}, which {ORIGINAL_FILE} does '
                              'not').passed and ok
    if ok:
        verdict.expect(True, f'{given}: the same nodes as {ORIGINAL_FILE} '
                             f'({", ".join(original.nodes)})', '')
    return ok


def _same_parameters(verdict: Verdict, original: LaunchProbe, twin: LaunchProbe,
                     given: str) -> None:
    for node in original.nodes:
        expected = (original.inspected or {}).get(node) or {}
        got = (twin.inspected or {}).get(node)
        if got is None:
            verdict.fail(f'{given}, {node} did not answer, so its parameters could not be read')
            continue
        wrong = [f'{name} {_shown(got.get(name))}, {ORIGINAL_FILE} gives {_shown(value)}'
                 for name, value in sorted(expected.items())
                 if got.get(name) != value or type(got.get(name)) is not type(value)]
        verdict.expect(not wrong, f'{given}, {node} has the same parameters',
                       f'{given}, {node} got ' + '; '.join(wrong))


def _same_topics(verdict: Verdict, original: LaunchProbe, twin: LaunchProbe,
                 given: str) -> None:
    remap = ("a remap goes from the name in the node's code to the new one: "
             '<remap from="distance" to="scan_range"/>')
    for node in original.nodes:
        for verb, topics_of in (('publishes', published_by), ('reads', read_by)):
            expected, got = topics_of(original, node), topics_of(twin, node)
            verdict.expect(got == expected,
                           f'{given}, {node} {verb} {", ".join(expected) or "nothing"}',
                           f'{given}, {node} {verb} {", ".join(got) or "nothing"}; in '
                           f'{ORIGINAL_FILE} it {verb} {", ".join(expected) or "nothing"}: '
                           + remap)


def _probe_original(package: StudentPackage, arguments: dict[str, str]) -> LaunchProbe:
    """The book's Python file, run as the student's terminal would run it."""
    book = StudentPackage(package.workspace, ORIGINAL_PACKAGE)
    run = probe(book, ORIGINAL_FILE, arguments=arguments, inspect=_all_parameters)
    if run.exited_by_itself or not run.nodes:
        raise LabkitError(f"`{run.command}` (the book's file) did not start: "
                          + '\n'.join(run.lines[-5:]))
    return run


def check_rover(package: StudentPackage, verdict: Verdict) -> Verdict:
    """ex611_rover.launch.xml starts the same system as twin_rover.launch.py."""
    if not requirements.files_installed(verdict, package):
        return verdict
    original_arguments = show_args(StudentPackage(package.workspace, ORIGINAL_PACKAGE),
                                   ORIGINAL_FILE)[0]
    if not _arguments_match(verdict, package, original_arguments):
        return verdict
    for arguments in RUNS:
        given = ('with ' + ' '.join(f'{k}:={v}' for k, v in arguments.items())
                 if arguments else 'with the defaults')
        original = _probe_original(package, arguments)
        twin = probe(package, TWIN_FILE, original.nodes, arguments=arguments,
                     inspect=_all_parameters)
        if _nodes_crashed(verdict, twin) or not requirements.launch_ran(verdict, twin):
            return verdict
        if _same_nodes(verdict, original, twin, given):
            _same_parameters(verdict, original, twin, given)
            _same_topics(verdict, original, twin, given)
        requirements.names_unique(verdict, twin)
    return verdict


EXERCISES = (
    Exercise('ex611_rover', 'Exercise 6.11.1 (the XML twin of a Python launch file)',
             ('launch/' + TWIN_FILE,), check_rover),
)
