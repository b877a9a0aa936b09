"""The running check: robot_system.launch.py running, checked against specs that it
meets and specs that it does not (nodes, types, endpoints, rates, parameters, QoS)."""
from __future__ import annotations

import labkit
import pytest
import rclpy
from rclpy.context import Context
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from speccheck import Status, check_live, load_spec
from std_msgs.msg import Float32

from .._polling import wait_for

pytestmark = pytest.mark.ros  # launches systems and checks them live

MET, FAILED = Status.MET, Status.FAILED
WINDOW = 2.0


@pytest.fixture(scope='module')
def robot_system(ros_env):
    with labkit.launch('my_robot_pkg', 'robot_system.launch.py', env=ros_env) as run:
        run.wait_for_nodes(['/sensor_publisher', '/data_processor'])
        yield run


def statuses(report, requirement):
    return [f.status for f in report.findings if f.requirement == requirement]


def evidence(report, requirement):
    return ' | '.join(f.evidence for f in report.findings if f.requirement == requirement)


def test_a_system_that_meets_its_spec(robot_system, write_spec):
    spec = load_spec(write_spec("""\
nodes:
  /sensor_publisher:
    parameters:
      publish_rate: {type: double, value: 2.0}
  /data_processor:
    parameters:
      window_size: {type: integer, min: 1, max: 10}
topics:
  /distance:
    type: std_msgs/msg/Float32
    publishers: [/sensor_publisher]
    subscribers: [/data_processor]
    rate: {min: 1.0, max: 3.0}
"""))
    report = check_live(spec, window=WINDOW)
    report.assert_ok()
    assert statuses(report, 'node /sensor_publisher') == [MET]
    assert evidence(report, 'node /data_processor: parameter window_size') == '3'
    assert statuses(report, 'topic /distance: type') == [MET]
    assert evidence(report, 'topic /distance: publisher /sensor_publisher') == \
        '/sensor_publisher publishes /distance'
    assert evidence(report, 'topic /distance: rate 1..3 Hz').startswith('measured ')
    assert '/sensor_publisher (reliable, volatile)' in evidence(report, 'topic /distance: QoS')


def test_a_system_that_does_not_meet_its_spec(robot_system, write_spec):
    spec = load_spec(write_spec("""\
nodes:
  /lidar: {}
  /sensor_publisher:
    parameters:
      publish_rate: {type: double, min: 5.0}
      frame_id: {type: string}
topics:
  /distance:
    type: sensor_msgs/msg/Range
    publishers: [/data_processor]
    rate: {min: 10.0}
  /robot1/distance:
    publishers: [/sensor_publisher]
"""))
    report = check_live(spec, window=WINDOW)
    assert not report.ok and report.exit_code == 1
    assert evidence(report, 'node /lidar').startswith('not running; running: ')
    assert evidence(report, 'node /sensor_publisher: parameter publish_rate') == \
        'value 2.0 is below the minimum 5'
    assert evidence(report, 'node /sensor_publisher: parameter frame_id').startswith(
        'the node has no such parameter; it has: publish_rate')
    assert evidence(report, 'topic /distance: type') == \
        'std_msgs/msg/Float32, the spec says sensor_msgs/msg/Range'
    assert evidence(report, 'topic /distance: publisher /data_processor') == (
        '/distance: expected publisher /data_processor, found /sensor_publisher; '
        '/data_processor publishes /distance_filtered')
    assert statuses(report, 'topic /distance: rate 10..inf Hz') == [FAILED]
    assert evidence(report, 'topic /robot1/distance') == (
        'no node publishes or subscribes to /robot1/distance; topics with that base name: '
        '/distance')
    # codes and spec lines of the JSON, JUnit and SARIF reports
    assert {(f.requirement, f.code, f.line) for f in report.failures} == {
        ('node /lidar', 'NodeMissing', 2),
        ('node /sensor_publisher: parameter publish_rate', 'ParameterMismatch', 5),
        ('node /sensor_publisher: parameter frame_id', 'ParameterMissing', 6),
        ('topic /distance: type', 'TypeMismatch', 9),
        ('topic /distance: publisher /data_processor', 'PublisherMissing', 10),
        ('topic /distance: rate 10..inf Hz', 'RateMismatch', 11),
        ('topic /robot1/distance', 'TopicMissing', 12),
    }


def wait_until_seen(topic, publishers, subscribers, timeout=10.0):
    """Wait until labkit's observer has discovered these endpoints (new in this process)."""
    def seen() -> bool:
        found = labkit.graph().topics.get(topic)
        return bool(found) and (found.publishers, found.subscribers) == (publishers, subscribers)

    wait_for(seen, timeout, f'the endpoints of {topic} to be discovered')


@pytest.fixture
def mismatched_qos():
    """A best-effort publisher and a reliable subscriber on /qos_probe (they never talk)."""
    context = Context()
    rclpy.init(args=[], context=context, signal_handler_options=SignalHandlerOptions.NO)
    talker = rclpy.create_node('qos_talker', context=context)
    listener = rclpy.create_node('qos_listener', context=context)
    talker.create_publisher(Float32, '/qos_probe',
                            QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT))
    listener.create_subscription(Float32, '/qos_probe', lambda msg: None,
                                 QoSProfile(depth=5, reliability=ReliabilityPolicy.RELIABLE))
    wait_until_seen('/qos_probe', ('/qos_talker',), ('/qos_listener',))
    yield
    talker.destroy_node()
    listener.destroy_node()
    context.try_shutdown()


def test_incompatible_qos_is_found(mismatched_qos, write_spec):
    spec = load_spec(write_spec('topics:\n  /qos_probe:\n    publishers: [/qos_talker]\n'
                                '    subscribers: [/qos_listener]\n'))
    report = check_live(spec, window=WINDOW)
    assert statuses(report, 'topic /qos_probe: publisher /qos_talker') == [MET]
    assert statuses(report, 'topic /qos_probe: QoS') == [FAILED]
    assert [f.code for f in report.find('topic /qos_probe: QoS')] == ['QoSMismatch']
    found = evidence(report, 'topic /qos_probe: QoS')
    assert found.startswith('publisher /qos_talker (best_effort, volatile) and subscriber '
                            '/qos_listener (reliable, volatile): ')
    assert 'reliab' in found.lower().split(': ', 1)[1]
