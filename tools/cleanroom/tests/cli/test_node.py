"""`ros2 node list|info` against running nodes, in Jazzy's formats."""
from __future__ import annotations

import pytest

SENSOR_PUBLISHER_INFO = """\
/sensor_publisher
  Subscribers:

  Publishers:
    /chatter: std_msgs/msg/String
    /parameter_events: rcl_interfaces/msg/ParameterEvent
    /rosout: rcl_interfaces/msg/Log
  Service Servers:
    /sensor_publisher/describe_parameters: rcl_interfaces/srv/DescribeParameters
    /sensor_publisher/get_parameter_types: rcl_interfaces/srv/GetParameterTypes
    /sensor_publisher/get_parameters: rcl_interfaces/srv/GetParameters
    /sensor_publisher/get_type_description: type_description_interfaces/srv/GetTypeDescription
    /sensor_publisher/list_parameters: rcl_interfaces/srv/ListParameters
    /sensor_publisher/set_parameters: rcl_interfaces/srv/SetParameters
    /sensor_publisher/set_parameters_atomically: rcl_interfaces/srv/SetParametersAtomically
  Service Clients:

  Action Servers:

  Action Clients:

"""


@pytest.fixture(scope='module', autouse=True)
def nodes(start_node, ros2):
    # With the daemon up first, start_node waits until it lists each node (a fresh
    # daemon answers with what it has discovered so far, as Jazzy's does).
    ros2('daemon', 'start')
    start_node('talker')
    start_node('listener')


def test_list_shows_visible_nodes_sorted(ros2):
    result = ros2('node', 'list')
    assert (result.returncode, result.stdout, result.stderr) == (
        0, '/listener\n/sensor_publisher\n', '')  # distinct names: no warning


def test_list_all_includes_the_hidden_command_node(ros2):
    lines = ros2('node', 'list', '-a').stdout.splitlines()
    assert lines[-2:] == ['/listener', '/sensor_publisher']
    assert any(line.startswith('/_ros2cli_') for line in lines)


def test_list_count(ros2):
    assert ros2('node', 'list', '--count-nodes').stdout == '2\n'


def test_info_matches_jazzy_layout(ros2):
    result = ros2('node', 'info', '/sensor_publisher')
    assert (result.returncode, result.stdout, result.stderr) == (0, SENSOR_PUBLISHER_INFO, '')


def test_info_lists_subscriptions(ros2):
    out = ros2('node', 'info', 'listener').stdout
    assert '  Subscribers:\n    /chatter: std_msgs/msg/String\n' \
           '    /cmd_vel: geometry_msgs/msg/Twist\n  Publishers:\n' in out


def test_info_of_unknown_node_fails(ros2):
    result = ros2('node', 'info', '/nope')
    assert (result.returncode, result.stdout) == (1, '')
    assert result.stderr == "Unable to find node '/nope'\n"


@pytest.mark.parametrize('args', [['bogus'], ['info']])
def test_bad_arguments_are_usage_errors(ros2, args):
    result = ros2('node', *args)
    assert result.returncode == 2
    assert result.stderr.startswith('usage: ros2 node')


def test_unknown_option_is_reported_by_the_top_level_parser(ros2):
    """ros2cli parses the whole line with its `ros2` parser, which rejects leftovers."""
    result = ros2('node', 'list', '--bogus')
    assert (result.returncode, result.stdout) == (2, '')
    assert result.stderr.splitlines() == [
        'usage: ros2 [-h] [--use-python-default-buffering]',
        '            Call `ros2 <command> -h` for more detailed usage. ...',
        'ros2: error: unrecognized arguments: --bogus']


NODE_HELP = """\
usage: ros2 node [-h]
                 Call `ros2 node <command> -h` for more detailed usage. ...

Various node related sub-commands

options:
  -h, --help            show this help message and exit

Commands:
  info  Output information about a node
  list  Output a list of available nodes

  Call `ros2 node <command> -h` for more detailed usage.
"""


@pytest.mark.parametrize('args', [(), ('-h',)])
def test_without_a_verb_it_prints_its_help_as_jazzy_does(ros2, args):
    """The sub-verbs sorted, in one aligned block, then the hint (seen on Jazzy)."""
    assert (ros2('node', *args).returncode, ros2('node', *args).stdout) == (0, NODE_HELP)
