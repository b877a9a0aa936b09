"""Checks of lesson 6.4 (Packaging launch and config files).

They build nothing: they look at what `colcon build` installed in the
student's share folder, start the installed launch file, and judge the
parameters the controller got and the launch log (a parameter file that is
not there is only a warning in ROS 2 Jazzy: the node starts with its own
defaults, so the check must read both).
"""
from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

from labkit.checks.ch06_03 import CONTROLLER, parameter_is, parameters_of, show_args
from labkit.grading import requirements
from labkit.grading.exercise import Exercise, ExerciseVerdict
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

FAST_FILE = 'ex64_fast_robot.launch.py'
FAST_CONFIG = 'config/ex64_fast_robot.yaml'
PARAMS_FILE = 'ex64_params_file.launch.py'
SLOW_CONFIG = 'config/ex64_slow_robot.yaml'
NOT_A_FILE = re.compile(r'^\[WARNING\] \[launch_ros\.actions\.node\]: '
                        r'Parameter file path is not a file: (?P<path>.+)$')
#: The parameter file the check hands to `params_file:=` (written to a temporary folder).
OVERRIDE_NAME = 'from_the_command_line'
OVERRIDE_YAML = (f'robot_controller:\n  ros__parameters:\n    robot_name: "{OVERRIDE_NAME}"\n'
                 '    max_linear_speed: 0.7\n')


def files_installed(verdict: ExerciseVerdict, package: StudentPackage) -> bool:
    """Each of the exercise's files is in src/ and installed, current; a missing
    install names data_files (this lesson teaches them, so its checks say more
    than requirements.files_installed)."""
    ok = True
    for relative in verdict.files:
        installed = package.share / relative
        problem = package.installed_problem(relative)
        if problem and (package.source / relative).is_file() and not installed.is_file():
            problem = (f'{package.shown(package.source / relative)} is not installed (no '
                       f'{package.shown(installed)}): a data_files entry of setup.py must list '
                       f'it (the one for {Path(relative).parent}/ installs '
                       f'{Path(relative).parent}/*{Path(relative).suffix}), then run colcon '
                       f'build --packages-select {package.name}')
        ok = verdict.expect(problem is None,
                            f'{package.shown(package.source / relative)} is installed as '
                            f'{package.shown(installed)}', problem or '') and ok
    return ok


def _why_not_a_file(package: StudentPackage, path: str) -> str:
    """What to do about `Parameter file path is not a file: <path>`."""
    if not os.path.isabs(path):
        return (f'{path!r} is a relative path: it is looked up from the folder the terminal '
                'is in, not in your package. Use the installed file: '
                "PathJoinSubstitution([FindPackageShare('my_ws_exercises'), 'config', ...])"
                .replace('my_ws_exercises', package.name))
    target = Path(os.path.normpath(path))
    if target.is_relative_to(package.share):
        relative = target.relative_to(package.share)
        source = package.source / relative
        if source.is_file():
            return (f'{package.shown(source)} is in src/ but not installed: no data_files '
                    f'entry of setup.py matches it (config/ installs config/*.yaml only). '
                    f'Name it to match, or add an entry, then run colcon build '
                    f'--packages-select {package.name}')
        return (f'there is no {package.shown(source)} to install: write it, then run colcon '
                f'build --packages-select {package.name}')
    return (f'{path} does not exist. The file is installed with {package.name}: '
            f'FindPackageShare must name the package the file is installed with, '
            f"FindPackageShare('{package.name}')")


def parameter_files_found(verdict: Verdict, package: StudentPackage, run: LaunchProbe,
                          when: str) -> bool:
    """No `Parameter file path is not a file` warning in the launch log."""
    missing = [m['path'].strip() for line in run.lines if (m := NOT_A_FILE.match(line))]
    for path in missing:
        verdict.fail(f'{when}, launch warned "Parameter file path is not a file: {path}" and '
                     f'the controller started with its own defaults: '
                     + _why_not_a_file(package, path))
    return not missing


def check_fast_robot(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The installed parameter file reaches the controller through FindPackageShare."""
    if not files_installed(verdict, package):
        return verdict
    run = probe(package, FAST_FILE, (CONTROLLER,), inspect=parameters_of((CONTROLLER,)))
    if not requirements.launch_ran(verdict, run):
        return verdict
    if not requirements.node_running(verdict, run, CONTROLLER,
                                     "start Node(package='my_robot_pkg', "
                                     "executable='robot_controller', parameters=[...])"):
        return verdict
    parameter_files_found(verdict, package, run, 'When it started')
    source = f'from {FAST_CONFIG}'
    fix = (f'{FAST_CONFIG} must set it under robot_controller: ros__parameters:, and the '
           "launch file must pass the installed file in the Node's parameters=[...]")
    for name, value in (('robot_name', 'speedy'), ('update_rate', 25.0),
                        ('max_linear_speed', 1.2), ('enabled_sensors', ['camera'])):
        parameter_is(verdict, run, CONTROLLER, name, value, source, fix)
    return verdict


def check_params_file(package: StudentPackage, verdict: Verdict) -> Verdict:
    """params_file defaults to the installed slow configuration and can be overridden."""
    if not files_installed(verdict, package):
        return verdict
    shown, _ = show_args(package, PARAMS_FILE)
    argument = shown.get('params_file')
    if argument is None:
        verdict.fail(f'`ros2 launch {package.name} {PARAMS_FILE} --show-args` does not list '
                     "'params_file': declare it with DeclareLaunchArgument('params_file', ...)")
    else:
        verdict.expect(argument.default is not None, "--show-args lists 'params_file' with a "
                       'default', "--show-args lists 'params_file' with no default (so it is "
                       'required): give it default_value=PathJoinSubstitution([...]) naming '
                       f'the installed {SLOW_CONFIG}')
        verdict.expect(not argument.description.startswith('no description given'),
                       "'params_file' has a description", "'params_file' has no description: "
                       "add description='...'")
    run = probe(package, PARAMS_FILE, (CONTROLLER,), inspect=parameters_of((CONTROLLER,)))
    if not requirements.launch_ran(verdict, run):
        return verdict
    if requirements.node_running(verdict, run, CONTROLLER, "start Node(package='my_robot_pkg', "
                                 "executable='robot_controller', ...)"):
        parameter_files_found(verdict, package, run, 'With the default params_file')
        parameter_is(verdict, run, CONTROLLER, 'robot_name', 'slowpoke',
                     f'from the default params_file, the installed {SLOW_CONFIG}',
                     f'the default_value of params_file must be the installed {SLOW_CONFIG}, '
                     "and the Node's parameters=[LaunchConfiguration('params_file')]")
    with tempfile.TemporaryDirectory(prefix='ex64_') as folder:
        other = Path(folder) / 'other_robot.yaml'
        other.write_text(OVERRIDE_YAML)
        given = probe(package, PARAMS_FILE, (CONTROLLER,), arguments={'params_file': other},
                      inspect=parameters_of((CONTROLLER,)))
    if not requirements.launch_ran(verdict, given):
        return verdict
    if requirements.node_running(verdict, given, CONTROLLER,
                                 'it must start with params_file:=... too'):
        parameter_is(verdict, given, CONTROLLER, 'robot_name', OVERRIDE_NAME,
                     f'from params_file:={other}',
                     "the Node must get the file the argument names: "
                     "parameters=[LaunchConfiguration('params_file')]")
    return verdict


EXERCISES = (
    Exercise('ex64_fast_robot', 'Exercise 6.4.1 (ship a second configuration)',
             (FAST_CONFIG, 'launch/' + FAST_FILE), check_fast_robot),
    Exercise('ex64_params_file', 'Exercise 6.4.2 (the parameter file as a launch argument)',
             ('launch/' + PARAMS_FILE, SLOW_CONFIG), check_params_file),
)
