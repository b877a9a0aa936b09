"""`ros2 topic list|info|echo|hz` against running nodes, in Jazzy's formats."""
from __future__ import annotations

import re
import signal

import pytest
from ros2_cleanroom.rate_window import RateWindow

RATE_BLOCK = re.compile(r'average rate: (\d+\.\d{3})\n'
                        r'\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s window: (\d+)')


@pytest.fixture(scope='module', autouse=True)
def nodes(start_node):
    start_node('talker')
    start_node('listener')
    start_node('twister')


def test_list_with_types(ros2):
    result = ros2('topic', 'list', '-t')
    assert result.returncode == 0
    assert result.stdout == ('/chatter [std_msgs/msg/String]\n'
                             '/cmd_vel [geometry_msgs/msg/Twist]\n'
                             '/parameter_events [rcl_interfaces/msg/ParameterEvent]\n'
                             '/rosout [rcl_interfaces/msg/Log]\n')


def test_list_names_and_count(ros2):
    assert ros2('topic', 'list').stdout == '/chatter\n/cmd_vel\n/parameter_events\n/rosout\n'
    assert ros2('topic', 'list', '-c').stdout == '4\n'


def test_info_counts_other_nodes_endpoints(ros2):
    result = ros2('topic', 'info', '/chatter')
    assert (result.returncode, result.stdout) == (
        0, 'Type: std_msgs/msg/String\nPublisher count: 1\nSubscription count: 1\n')


def test_info_of_unknown_topic_fails(ros2):
    result = ros2('topic', 'info', '/nope')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', "Unknown topic '/nope'\n")


def test_echo_once_prints_one_yaml_message(ros2):
    result = ros2('topic', 'echo', '/chatter', '--once')
    assert result.returncode == 0
    assert re.fullmatch(r'data: hello \d+\n---\n', result.stdout), result.stdout


def test_echo_nests_submessages_in_field_order(ros2):
    result = ros2('topic', 'echo', '/cmd_vel', '--once')
    assert result.stdout == ('linear:\n  x: 0.5\n  y: 0.0\n  z: 0.0\n'
                             'angular:\n  x: 0.0\n  y: 0.0\n  z: -1.25\n---\n')


def test_echo_field_and_flow_style(ros2):
    assert ros2('topic', 'echo', '/cmd_vel', '--once', '--field', 'angular.z').stdout == \
        '-1.25\n---\n'
    assert ros2('topic', 'echo', '/cmd_vel', '--once', '--field', 'linear',
                '--flow-style').stdout == '{x: 0.5, y: 0.0, z: 0.0}\n---\n'


def test_echo_with_explicit_type(ros2):
    result = ros2('topic', 'echo', 'chatter', 'std_msgs/msg/String', '--once')
    assert result.stdout.startswith('data: hello ')


def test_echo_unknown_topic_warns_and_fails(ros2):
    result = ros2('topic', 'echo', '/nope', '--once')
    assert result.returncode == 1
    assert result.stdout == 'WARNING: topic [/nope] does not appear to be published yet\n'
    assert result.stderr == 'Could not determine the type for the passed topic\n'


def test_echo_invalid_type_fails(ros2):
    result = ros2('topic', 'echo', '/chatter', 'std_msgs/msg/Nope', '--once')
    assert (result.returncode, result.stderr) == (1, 'The passed message type is invalid\n')


def _hz_blocks(ros2_background, *args, blocks=2):
    """The first `blocks` reports of `ros2 topic hz /chatter`, then Ctrl-C."""
    proc = ros2_background('topic', 'hz', '/chatter', *args)
    lines = [proc.stdout.readline() for _ in range(2 * blocks)]
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=10)
    return ''.join(lines), proc.returncode, err


def test_hz_prints_rate_blocks_until_sigint(ros2_background):
    text, returncode, err = _hz_blocks(ros2_background)
    matches = RATE_BLOCK.findall(text)
    assert len(matches) == 2, text
    assert 5.0 < float(matches[0][0]) < 20.0  # the talker publishes at 10 Hz
    assert (returncode, err) == (0, '')


def test_hz_window_limits_the_samples(ros2_background):
    text, returncode, _ = _hz_blocks(ros2_background, '--window', '5', blocks=2)
    assert [int(window) for _, window in RATE_BLOCK.findall(text)] == [5, 5]
    assert returncode == 0


def test_rate_window_report_format():
    window = RateWindow(size=3)
    assert window.report() is None
    for stamp in (0.0, 0.1, 0.3, 0.4):
        window.add(stamp)
    assert window.report() == ('average rate: 6.667\n'
                               '\tmin: 0.100s max: 0.200s std dev: 0.05000s window: 3')
    assert window.report() == 'no new messages'


@pytest.mark.parametrize('args', [['bogus'], ['echo'], ['hz', '/chatter', '-w', 'x']])
def test_bad_arguments_are_usage_errors(ros2, args):
    result = ros2('topic', *args)
    assert result.returncode == 2
    assert result.stderr.startswith('usage: ros2 topic')
