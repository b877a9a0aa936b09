"""`ros2 action ...`; every expected output was recorded from Jazzy's `ros2` (the
reference).  The action server serves turtlesim's RotateAbsolute: ROS 2's
turtlesim where it is installed, else a stand-in built once
(interface_stand_in.py), since the PyPI wheels have no action type."""
from __future__ import annotations

import re

import pytest
from action_lifecycle_nodes import started
from interface_stand_in import environment


@pytest.fixture(scope='module')
def cli_env(cli_env):
    """The module's domain, with turtlesim's action type importable."""
    return environment(cli_env, 'turtlesim')

ACTION_HELP = """\
usage: ros2 action [-h]
                   Call `ros2 action <command> -h` for more detailed usage.
                   ...

Various action related sub-commands

options:
  -h, --help            show this help message and exit

Commands:
  info       Print information about an action
  list       Output a list of action names
  send_goal  Send an action goal
  type       Print a action's type

  Call `ros2 action <command> -h` for more detailed usage.
"""

SEND_GOAL_USAGE = """\
usage: ros2 action send_goal [-h] [--stdin] [-f]
                             action_name action_type [goal]
"""

SUCCEEDED = """\
Waiting for an action server to become available...
Sending goal:
     theta: 1.5

Goal accepted with ID: X

Feedback:
    remaining: 1.0

Result:
    delta: 0.75

Goal finished with status: SUCCEEDED
"""
#: The same run when the first feedback arrives before "Goal accepted" is printed.
FEEDBACK_FIRST = SUCCEEDED.replace('Goal accepted with ID: X\n\nFeedback:\n    remaining: 1.0\n\n',
                                   'Feedback:\n    remaining: 1.0\n\nGoal accepted with ID: X\n\n')


@pytest.fixture(scope='module')
def server(cli_env, daemon_listing):
    with started('action', cli_env):
        daemon_listing(('action', 'list'), ['/rotate'])
        yield


def test_help_and_usage_errors(ros2):
    assert ros2('action', '-h').stdout == ACTION_HELP
    result = ros2('action', 'send_goal', '--stdin', '/rotate', 'turtlesim/action/RotateAbsolute',
                  '{theta: 1.0}')
    assert (result.returncode, result.stderr) == (2, SEND_GOAL_USAGE + (
        'ros2 action send_goal: error: argument goal: not allowed with argument --stdin\n'))


def test_unknown_action_and_type(ros2):
    assert ros2('action', 'info', '/nope').stdout == (
        'Action: /nope\nAction clients: 0\nAction servers: 0\n')
    result = ros2('action', 'type', '/nope')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', '')
    result = ros2('action', 'send_goal', '/rotate', 'turtlesim/msg/Pose', '{theta: 1.0}')
    assert (result.returncode, result.stderr) == (1, 'The passed action type is invalid\n')


def test_list_info_type(server, ros2):
    assert ros2('action', 'list', '-t').stdout == '/rotate [turtlesim/action/RotateAbsolute]\n'
    assert ros2('action', 'info', 'rotate', '-t').stdout == (
        'Action: rotate\n'
        'Action clients: 1\n    /action_client [turtlesim/action/RotateAbsolute]\n'
        'Action servers: 1\n    /action_server [turtlesim/action/RotateAbsolute]\n')
    assert ros2('action', 'type', '/rotate').stdout == 'turtlesim/action/RotateAbsolute\n'
    assert ros2('action', 'type', 'rotate').returncode == 1  # taken as given, not as /rotate


def test_send_goal(server, ros2):
    result = ros2('action', 'send_goal', '-f', '/rotate', 'turtlesim/action/RotateAbsolute',
                  '{theta: 1.5}')
    assert result.returncode == 0
    # The first feedback may come before the acceptance is printed, on Jazzy too.
    assert re.sub('ID: [0-9a-f]{32}', 'ID: X', result.stdout) in (SUCCEEDED, FEEDBACK_FIRST)
    rejected = ros2('action', 'send_goal', '/rotate', 'turtlesim/action/RotateAbsolute',
                    '{theta: -1}')
    assert (rejected.returncode, rejected.stdout.splitlines()[-1]) == (0, 'Goal was rejected.')
    result = ros2('action', 'send_goal', '/rotate', 'turtlesim/action/RotateAbsolute',
                  '{thetax: 1.5}')
    assert (result.returncode, result.stderr) == (1, 'Failed to populate message fields: '
                                                     'AttributeError("\'RotateAbsolute_Goal\' '
                                                     'object has no attribute \'thetax\'")\n')
