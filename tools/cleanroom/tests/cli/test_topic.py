"""`ros2 topic list|info|echo|hz` against running nodes, in Jazzy's formats."""
from __future__ import annotations

import re
import signal

import pytest
from ros2_cleanroom.interfaces import message_to_csv
from ros2_cleanroom.rate_window import RateWindow
from std_msgs.msg import Float64MultiArray

STRING_HASH = 'RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18'
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


def endpoint_block(node: str, kind: str, reliability: str = 'RELIABLE') -> str:
    """The regex of one endpoint of `topic info -v` (the GID differs every run)."""
    return re.escape(
        f'Node name: {node}\n'
        'Node namespace: /\n'
        'Topic type: std_msgs/msg/String\n'
        f'Topic type hash: {STRING_HASH}\n'
        f'Endpoint type: {kind}\n') + r'GID: (?:[0-9a-f]{2}\.){15}[0-9a-f]{2}\n' + re.escape(
        'QoS profile:\n'
        f'  Reliability: {reliability}\n'
        '  History (Depth): UNKNOWN\n'
        '  Durability: VOLATILE\n'
        '  Lifespan: Infinite\n'
        '  Deadline: Infinite\n'
        '  Liveliness: AUTOMATIC\n'
        '  Liveliness lease duration: Infinite\n\n')


def test_info_verbose_lists_each_endpoint_with_qos(ros2):
    result = ros2('topic', 'info', '-v', '/chatter')
    assert result.returncode == 0
    expected = (re.escape('Type: std_msgs/msg/String\n\nPublisher count: 1\n\n')
                + endpoint_block('sensor_publisher', 'PUBLISHER')
                + re.escape('Subscription count: 1\n\n')
                + endpoint_block('listener', 'SUBSCRIPTION'))
    assert re.fullmatch(expected, result.stdout), result.stdout


def test_info_verbose_of_unknown_topic_fails(ros2):
    result = ros2('topic', 'info', '--verbose', '/nope')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', "Unknown topic '/nope'\n")


def test_echo_csv_prints_field_values_per_line(ros2):
    result = ros2('topic', 'echo', '--csv', '/chatter', '--once')
    assert result.returncode == 0
    assert re.fullmatch(r'hello \d+\n', result.stdout), result.stdout


def test_echo_csv_flattens_nested_messages(ros2):
    result = ros2('topic', 'echo', '--csv', '/cmd_vel', '--once')
    assert (result.returncode, result.stdout) == (0, '0.5,0.0,0.0,0.0,0.0,-1.25\n')


def test_csv_keeps_the_place_of_an_empty_array():
    msg = Float64MultiArray(data=[1.0, 2.5])  # layout: dim=[] (empty), data_offset=0
    assert message_to_csv(msg) == ',0,1.0,2.5'
    assert message_to_csv(Float64MultiArray(data=[0.5] * 3), truncate_length=2) == \
        ',0,0.5,0.5,...'


def test_echo_timeout_without_messages_prints_nothing(ros2):
    result = ros2('topic', 'echo', '--csv', '/parameter_events', '--once', '--timeout', '2')
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')


def test_echo_timeout_ends_a_stream_of_messages(ros2):
    result = ros2('topic', 'echo', '--csv', '/chatter', '--timeout', '2')
    lines = result.stdout.splitlines()
    assert (result.returncode, result.stderr) == (0, '')
    assert len(lines) > 1 and all(re.fullmatch(r'hello \d+', line) for line in lines), lines


def test_echo_filter_selects_messages(ros2):
    result = ros2('topic', 'echo', '/chatter', '--once', '--filter', 'm.data.endswith("7")')
    assert re.fullmatch(r'data: hello \d*7\n---\n', result.stdout), result.stdout


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


def test_echo_of_an_unpublished_topic_with_its_type_waits_without_a_warning(ros2):
    """Jazzy warns only when it must find the type in the graph; with the type given it
    subscribes and waits (here until --timeout), exit 0."""
    result = ros2('topic', 'echo', '/nope', 'std_msgs/msg/String', '--once', '--timeout', '1')
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')


def test_echo_invalid_type_fails(ros2):
    result = ros2('topic', 'echo', '/chatter', 'std_msgs/msg/Nope', '--once')
    assert (result.returncode, result.stderr) == (1, 'The passed message type is invalid\n')


def _hz_blocks(ros2_background, *args, blocks=2):
    """The first `blocks` rate reports of `ros2 topic hz /chatter`, then Ctrl-C.

    Reads whole reports, however many other lines come between them: on a
    loaded machine a second can pass without a message ("no new messages"),
    which is hz's behaviour too, not a broken report.
    """
    proc = ros2_background('topic', 'hz', '/chatter', *args)
    reports: list[str] = []
    for _ in range(50):  # a hang guard on lines read, not a time limit
        line = proc.stdout.readline()
        if not line:
            break
        if line.startswith('average rate:'):
            reports.append(line + proc.stdout.readline())
            if len(reports) == blocks:
                break
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=10)
    return ''.join(reports), proc.returncode, err


def test_hz_prints_rate_blocks_until_sigint(ros2_background):
    text, returncode, err = _hz_blocks(ros2_background)
    matches = RATE_BLOCK.findall(text)
    assert len(matches) == 2, text
    assert 2.0 < float(matches[0][0]) < 50.0  # the talker publishes at 10 Hz (a rate, not a period)
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


@pytest.mark.parametrize('args', [['bogus'], ['echo'], ['hz', '/chatter', '-w', 'x'],
                                  ['echo', '/chatter', '--timeout', 'x'], ['info']])
def test_bad_arguments_are_usage_errors(ros2, args):
    result = ros2('topic', *args)
    assert result.returncode == 2
    assert result.stderr.startswith('usage: ros2 topic')


def test_doctor_passes_on_a_healthy_graph(ros2):
    """Every topic here has a publisher and a subscriber with matching QoS."""
    result = ros2('doctor')
    assert (result.returncode, result.stdout, result.stderr) == (0, '\nAll 3 checks passed\n\n', '')
