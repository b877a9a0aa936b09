"""labkit.rates: rate and serialized size of the messages on a topic, with a
subscription that matches the publisher's reliability (large messages sent
best effort lose fragments, so `ros2 topic hz` subscribes reliably when it can)."""
from __future__ import annotations

import threading
import time
from collections.abc import Iterator

import pytest
import rclpy
from labkit import observer
from labkit.rates import matching_qos, measure_rates
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.serialization import serialize_message
from speccheck import rates
from std_msgs.msg import String

from tests._polling import wait_for

pytestmark = pytest.mark.ros  # publishes and subscribes on a ROS graph

RATE = 20.0  # Hz the test publisher is timed at
WINDOW = 3.0  # seconds of measurement
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging


class Talker:
    """A publisher in its own context, spun in a thread, sending one fixed message."""

    def __init__(self, topic: str, reliability: ReliabilityPolicy, text: str) -> None:
        self.message = String(data=text)
        self.context = Context()
        rclpy.init(context=self.context)
        self.node = rclpy.create_node('rates_talker', context=self.context)
        publisher = self.node.create_publisher(
            String, topic, QoSProfile(depth=10, reliability=reliability))
        self.node.create_timer(1.0 / RATE, lambda: publisher.publish(self.message))
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.thread = threading.Thread(target=self.executor.spin, daemon=True)
        self.thread.start()

    def close(self) -> None:
        self.executor.shutdown()
        self.thread.join(timeout=HANG_GUARD)
        self.node.destroy_node()
        self.context.try_shutdown()


def _talker(topic: str, reliability: ReliabilityPolicy, text: str) -> Iterator[Talker]:
    talker = Talker(topic, reliability, text)
    node = observer.observer().node
    wait_for(lambda: node.get_publishers_info_by_topic(topic), HANG_GUARD,
             f'the observer to discover the publisher of {topic}')
    try:
        yield talker
    finally:
        talker.close()


@pytest.fixture
def reliable_talker() -> Iterator[Talker]:
    yield from _talker('/rates_reliable', ReliabilityPolicy.RELIABLE, 'r' * 1000)


@pytest.fixture
def best_effort_talker() -> Iterator[Talker]:
    yield from _talker('/rates_best_effort', ReliabilityPolicy.BEST_EFFORT, 'b' * 10)


def test_rate_and_size_of_a_topic(reliable_talker):
    rate = measure_rates({'/rates_reliable': 'std_msgs/msg/String'}, window=WINDOW)[
        '/rates_reliable']
    assert RATE / 3 <= rate.hz <= RATE * 1.2, rate
    assert rate.size == len(serialize_message(reliable_talker.message)), rate
    assert rate.bytes_per_second == pytest.approx(rate.hz * rate.size)


def test_a_measuring_process_that_falls_behind_still_times_the_publisher(
        reliable_talker, monkeypatch):
    """Each message is timed by when it was published: an observer that takes one
    message per SLOW seconds (a loaded machine) still measures the talker's rate,
    which it could never measure by timing the messages as it takes them."""
    slow = 0.25  # seconds per message taken: at most 4 Hz timed on arrival
    taken = rates._arrived

    def slow_arrival(seen, raw, info) -> None:  # rclpy passes the info to two parameters
        time.sleep(slow)
        taken(seen, raw, info)

    monkeypatch.setattr(rates, '_arrived', slow_arrival)
    rate = measure_rates({'/rates_reliable': 'std_msgs/msg/String'}, window=WINDOW)[
        '/rates_reliable']
    assert rate.count >= 2 and RATE / 3 <= rate.hz <= RATE * 1.2, rate
    assert rate.hz > 1.5 / slow, rate


def test_subscription_matches_the_publishers_reliability(reliable_talker, best_effort_talker):
    node = observer.observer().node
    assert matching_qos(node, '/rates_reliable').reliability == ReliabilityPolicy.RELIABLE
    assert matching_qos(node, '/rates_best_effort').reliability == \
        ReliabilityPolicy.BEST_EFFORT
    assert matching_qos(node, '/rates_nobody').reliability == ReliabilityPolicy.BEST_EFFORT
    rate = measure_rates({'/rates_best_effort': 'std_msgs/msg/String'}, window=WINDOW)[
        '/rates_best_effort']
    assert rate.size == len(serialize_message(best_effort_talker.message)), rate


def test_a_silent_topic_has_no_rate_and_no_size():
    rate = measure_rates({'/rates_nobody': 'std_msgs/msg/String'}, window=0.5)[
        '/rates_nobody']
    assert (rate.count, rate.hz, rate.size, rate.bytes_per_second) == (0, None, None, None)
