"""Errors end the launch with Jazzy's wording, exit code 1, and no process left."""
from __future__ import annotations

import textwrap

import pytest
from launch.actions import (
    DeclareLaunchArgument,
    ExecuteProcess,
    IncludeLaunchDescription,
    LogInfo,
    OpaqueFunction,
    TimerAction,
)
from launch.launch_description_sources import (
    AnyLaunchDescriptionSource,
    PythonLaunchDescriptionSource,
)
from launch.substitutions import LaunchConfiguration

PREFIX = '[ERROR] [launch]: Caught exception in launch (see debug for traceback): '


def _error(result):
    lines = [line for line in result.output.splitlines() if line.startswith(PREFIX)]
    assert len(lines) == 1, result.output
    return lines[0][len(PREFIX):]


def _file(tmp_path, name, body):
    path = tmp_path / name
    path.write_text(textwrap.dedent(body))
    return str(path)


CHILD = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument
    from launch.conditions import IfCondition

    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument('child_name', default_value='child'),
            DeclareLaunchArgument('rate', description='Publishing rate in Hz'),
            DeclareLaunchArgument('optional', condition=IfCondition('false')),
        ])
"""


def test_missing_required_argument_of_an_include(run_launch, tmp_path):
    child = _file(tmp_path, 'child.launch.py', CHILD)
    result = run_launch([
        ExecuteProcess(cmd=['sleep', '20'], name='early'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                 launch_arguments={'child_name': 'orphan'}.items()),
    ])
    assert result.returncode == 1
    assert _error(result) == ("Included launch description missing required argument 'rate' "
                              "(description: 'Publishing rate in Hz'), given: [child_name]")
    assert "sending signal 'SIGINT' to process[early-1]" in result.output


def test_required_argument_given_by_include(run_launch, tmp_path):
    child = _file(tmp_path, 'child.launch.py', CHILD)
    result = run_launch([IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                                  launch_arguments=[('rate', '1')])])
    assert result.returncode == 0


def test_required_argument_at_top_level(run_launch):
    result = run_launch([DeclareLaunchArgument('needed', description='Needed value')])
    assert _error(result) == ('Required launch argument "needed" (description: '
                              '"Needed value") was not provided')


def test_invalid_choice(run_launch):
    result = run_launch([DeclareLaunchArgument('mode', default_value='sim',
                                               choices=['sim', 'real'])], argv=('mode:=fly',))
    refusal = ('Argument "mode" provided value "fly" is not valid. '
               "Valid options are: ['sim', 'real']")
    assert _error(result) == refusal
    # Jazzy first logs the refusal under the action's own logger (errors/ golden 26).
    error_lines = [line for line in result.output.splitlines() if line.startswith('[ERROR]')]
    assert error_lines == ['[ERROR] [launch.actions.declare_launch_argument]: ' + refusal,
                           PREFIX + refusal]
    with pytest.raises(RuntimeError, match='not in provided choices'):
        DeclareLaunchArgument('mode', default_value='x', choices=['a'])


def test_undeclared_configuration(run_launch):
    result = run_launch([LogInfo(msg=LaunchConfiguration('robot_name'))])
    assert _error(result) == "launch configuration 'robot_name' does not exist"
    assert result.returncode == 1


def test_syntax_error_is_reported_like_python(run_launch, tmp_path):
    path = _file(tmp_path, 'broken.launch.py', """
        def generate_launch_description():
            return [
                (1, 2
            ]
    """)
    result = run_launch([IncludeLaunchDescription(PythonLaunchDescriptionSource(path))])
    assert _error(result) == ("closing parenthesis ']' does not match opening parenthesis '(' "
                              'on line 4 (broken.launch.py, line 5)')
    assert result.returncode == 1


def test_no_generate_function_python_and_any_sources(run_launch, tmp_path):
    path = _file(tmp_path, 'empty.launch.py', 'x = 1\n')
    result = run_launch([IncludeLaunchDescription(PythonLaunchDescriptionSource(path))])
    message = (f"launch file at '{path}' does not contain the required function "
               "'generate_launch_description()'")
    assert _error(result) == message
    result = run_launch([IncludeLaunchDescription(AnyLaunchDescriptionSource(path))])
    assert result.output.splitlines()[-3:] == [
        PREFIX + 'Caught multiple exceptions when trying to load file of format [py]:',
        ' - InvalidPythonLaunchFileError: ' + message,
        ' - InvalidFrontendLaunchFileError: The launch file may have a syntax error, '
        'or its format is unknown']


def test_exception_in_a_timer_stops_running_processes(run_launch):
    def fail(context):
        raise ValueError('late failure')

    result = run_launch([
        ExecuteProcess(cmd=['sleep', '20'], name='victim'),
        TimerAction(period=0.2, actions=[OpaqueFunction(function=fail)]),
    ], debug=True)
    assert _error(result) == 'late failure'
    assert 'Traceback (most recent call last)' in result.output  # debug mode shows it
    assert '[ERROR] [victim-1]: process has died' in result.output
    assert result.returncode == 1


def test_debug_puts_the_event_loop_in_asyncio_debug_mode(run_launch):
    seen = []

    def record(context):
        seen.append(context.asyncio_loop.get_debug())

    run_launch([OpaqueFunction(function=record)], debug=True)
    run_launch([OpaqueFunction(function=record)])
    assert seen == [True, False]


def test_functions_returning_non_entities_are_reported(run_launch):
    result = run_launch([OpaqueFunction(function=lambda context: True)])
    assert _error(result) == ("expected None, a launch entity or a list of launch entities, "
                              "got 'bool'")
    result = run_launch([OpaqueFunction(function=lambda context: ['not an action'])])
    assert "got an item of type 'str'" in _error(result)
