"""`ros2 doctor [--report]` on a graph with a QoS mismatch and lonely endpoints.

The module's graph: talker -> listener on /chatter (healthy; the listener also
subscribes to /cmd_vel, which nobody publishes), a best-effort publisher and a
reliable subscription on /qos_topic (incompatible: the subscription receives
nothing), and a publisher on /lonely nobody reads.
"""
from __future__ import annotations

import re
from types import SimpleNamespace

import pytest
from _polling import wait_for
from rclpy.qos import QoSCompatibility, QoSProfile
from ros2_cleanroom.doctor_graph import (
    QosPair,
    TopicEndpoints,
    lonely_endpoint_warnings,
    qos_errors,
    qos_pairs,
)
from ros2_cleanroom.doctor_report import format_section, qos_rows
from ros2_cleanroom.network_info import format_flags, interfaces
from ros2_cleanroom.verbs.doctor import summary

QOS_ERROR = ("ERROR: QoS compatibility error found on topic '/qos_topic': "
             'Best effort publisher and reliable subscription;')
WARNING_LINE = re.compile(r'^\S+\.py: \d+: UserWarning: (.*)$')


@pytest.fixture(scope='module', autouse=True)
def nodes(start_node, ros2):
    for kind in ('talker', 'listener', 'qos_publisher', 'qos_subscriber', 'lonely_talker'):
        start_node(kind)
    # Endpoints can be discovered before their node's name (ros2 then prints
    # _NODE_NAME_UNKNOWN_, as Jazzy does); the tests read a settled graph.
    wait_for(lambda: '_NODE_NAME_UNKNOWN_' not in ros2('topic', 'info', '-v', '/qos_topic').stdout,
             30, 'the node names of /qos_topic to be discovered')


def warnings_of(stderr: str) -> list[str]:
    """The messages of the `<file>: <line>: UserWarning: <message>` lines, in order."""
    lines = stderr.splitlines()
    assert all(WARNING_LINE.match(line) for line in lines), stderr
    return [WARNING_LINE.match(line).group(1) for line in lines]


def test_topic_info_verbose_shows_the_mismatched_reliability(ros2):
    out = ros2('topic', 'info', '-v', '/qos_topic').stdout
    publishers, subscriptions = out.split('Subscription count: 1\n')
    assert 'Publisher count: 1\n' in publishers
    assert 'Node name: qos_publisher\n' in publishers
    assert '  Reliability: BEST_EFFORT\n' in publishers
    assert 'Node name: qos_subscriber\n' in subscriptions
    assert '  Reliability: RELIABLE\n' in subscriptions


def test_doctor_fails_the_middleware_check_and_warns_on_stderr(ros2):
    result = ros2('doctor')
    assert result.returncode == 0  # Jazzy exits 0 even with a failed check
    assert result.stdout == '\n1/3 check(s) failed\n\nFailed modules: middleware\n'
    assert warnings_of(result.stderr) == [
        QOS_ERROR, 'Subscriber without publisher detected on /cmd_vel.',
        'Publisher without subscriber detected on /lonely.']


def test_doctor_warnings_are_python_warnings(ros2):
    result = ros2('doctor', env={'PYTHONWARNINGS': 'ignore'})
    assert (result.stdout, result.stderr) == (
        '\n1/3 check(s) failed\n\nFailed modules: middleware\n', '')


def test_include_warnings_fails_the_topic_check_too(ros2):
    result = ros2('wtf', '--include-warnings', env={'PYTHONWARNINGS': 'ignore'})
    assert (result.returncode, result.stdout) == (
        0, '\n2/3 check(s) failed\n\nFailed modules: middleware topic\n')


def test_report_sections_in_order(ros2):
    result = ros2('doctor', '--report')
    assert result.returncode == 0
    titles = [line.strip() for line in result.stdout.splitlines() if line.startswith('   ')]
    assert titles == ['NETWORK CONFIGURATION', 'PLATFORM INFORMATION', 'QOS COMPATIBILITY LIST',
                      'RMW MIDDLEWARE', 'TOPIC LIST']
    assert result.stdout.startswith('\n   NETWORK CONFIGURATION\ninet         : 127.0.0.1\n')
    assert '\nmiddleware name    : rmw_fastrtps_cpp\n' in result.stdout


def test_report_lists_each_pair_with_its_qos_status(ros2):
    out = ros2('doctor', '-r').stdout
    qos = out.split('   QOS COMPATIBILITY LIST\n')[1].split('\n\n')[0]
    assert qos == (
        'topic [type]            : /chatter [std_msgs/msg/String]\n'
        'publisher node          : sensor_publisher\n'
        'subscriber node         : listener\n'
        'compatibility status    : OK\n'
        'topic [type]            : /qos_topic [std_msgs/msg/String]\n'
        'publisher node          : qos_publisher\n'
        'subscriber node         : qos_subscriber\n'
        'compatibility status    : ERROR: Best effort publisher and reliable subscription;')


def test_report_topic_list_counts_endpoints(ros2):
    out = ros2('doctor', '--report').stdout
    assert out.endswith(
        '   TOPIC LIST\n'
        'topic               : /chatter\npublisher count     : 1\nsubscriber count    : 1\n'
        'topic               : /cmd_vel\npublisher count     : 0\nsubscriber count    : 1\n'
        'topic               : /lonely\npublisher count     : 1\nsubscriber count    : 0\n'
        'topic               : /qos_topic\npublisher count     : 1\nsubscriber count    : 1\n')


def test_report_failed_shows_only_the_failed_modules_sections(ros2):
    out = ros2('doctor', '--report-failed', env={'PYTHONWARNINGS': 'ignore'}).stdout
    titles = [line.strip() for line in out.splitlines() if line.startswith('   ')]
    assert titles == ['QOS COMPATIBILITY LIST', 'RMW MIDDLEWARE']


def test_unknown_arguments_are_rejected_by_ros2(ros2):
    result = ros2('doctor', '--bogus')
    assert (result.returncode, result.stdout) == (2, '')
    assert result.stderr.startswith('usage: ros2 ')
    assert result.stderr.splitlines()[-1] == 'ros2: error: unrecognized arguments: --bogus'


def test_a_word_after_the_options_is_taken_for_a_sub_verb(ros2):
    """Jazzy: doctor's one sub-verb is `hello`, so `extra` is an invalid choice."""
    result = ros2('doctor', '--report', 'extra')
    assert (result.returncode, result.stdout) == (2, '')
    assert result.stderr.startswith('usage: ros2 doctor ')
    assert result.stderr.splitlines()[-1] == (
        'ros2 doctor: error: argument Call `ros2 doctor <command> -h` for more detailed '
        "usage.: invalid choice: 'extra' (choose from 'hello')")


def test_section_keys_are_padded_to_the_longest_plus_four():
    assert format_section('RMW MIDDLEWARE', [('middleware name', 'x')]) == \
        '\n   RMW MIDDLEWARE\nmiddleware name    : x'
    assert format_section('T', [('ab', '1'), ('abcdef', '2')]) == \
        '\n   T\nab        : 1\nabcdef    : 2'


def test_loopback_interface_fields():
    loopback = next(fields for fields in interfaces() if fields['device'] == 'lo')
    assert (loopback['inet'], loopback['inet4'], loopback['netmask']) == \
        ('127.0.0.1', "['127.0.0.1']", '255.0.0.0')
    assert 'ether' not in loopback  # the all-zero MAC is left out
    assert re.fullmatch(r'\d+<(\w+,)*LOOPBACK(,\w+)*>', loopback['flags'])
    assert list(loopback).index('inet') < list(loopback).index('device') < \
        list(loopback).index('mtu')


def test_interface_flags_as_number_and_names():
    assert format_flags('up,broadcast,running,multicast') == '4163<UP,BROADCAST,RUNNING,MULTICAST>'
    assert format_flags('up,loopback,running') == '73<UP,LOOPBACK,RUNNING>'
    assert format_flags('broadcast,noarp') == '130<BROADCAST,NOARP>'


def test_findings_from_plain_endpoint_lists():
    topics = [TopicEndpoints('/a', ['x/msg/Y'], publishers=['p']),
              TopicEndpoints('/b', ['x/msg/Y'], subscribers=['s']),
              TopicEndpoints('/c', ['x/msg/Y'], publishers=['p'], subscribers=['s'])]
    assert lonely_endpoint_warnings(topics) == ['Publisher without subscriber detected on /a.',
                                                'Subscriber without publisher detected on /b.']
    pairs = [QosPair('/c', ['x/msg/Y'], 'p', 's', QoSCompatibility.ERROR, 'ERROR: why;'),
             QosPair('/c', ['x/msg/Y'], 'p', 't', QoSCompatibility.OK, '')]
    assert qos_errors(pairs) == ["ERROR: QoS compatibility error found on topic '/c': why;"]
    assert [pair.status for pair in pairs] == ['ERROR: why;', 'OK']


def test_a_pair_on_a_topic_with_two_types_shows_the_publisher_s_type():
    """As Jazzy's report of lesson 6.7's /range/rear: a Float64 publisher and a Float32
    subscription appear as `/range/rear [std_msgs/msg/Float64]`."""
    qos = QoSProfile(depth=10)
    publisher = SimpleNamespace(node_name='rear_sensor', topic_type='std_msgs/msg/Float64',
                                qos_profile=qos)
    subscriber = SimpleNamespace(node_name='obstacle_monitor',
                                 topic_type='std_msgs/msg/Float32', qos_profile=qos)
    topic = TopicEndpoints('/range/rear', ['std_msgs/msg/Float32', 'std_msgs/msg/Float64'],
                           publishers=[publisher], subscribers=[subscriber])
    (pair,) = qos_pairs([topic])
    assert qos_rows([pair])[0] == ('topic [type]', '/range/rear [std_msgs/msg/Float64]')


def test_summary_wording():
    assert summary([], 3) == '\nAll 3 checks passed\n'
    assert summary(['middleware'], 3) == '\n1/3 check(s) failed\n\nFailed modules: middleware'


def test_echo_of_a_topic_with_only_a_subscription_takes_its_type_without_a_warning(ros2):
    """This module's /cmd_vel has the listener's subscription and no publisher: Jazzy's
    echo finds the type in the graph, does not warn, and waits (here until --timeout)."""
    result = ros2('topic', 'echo', '/cmd_vel', '--once', '--timeout', '1')
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')
