"""labkit.rates waits for a topic's publishers before it picks the
subscription's reliability: measured right after a launch starts, a reliable
publisher not yet discovered would otherwise get a best effort subscription,
which loses large messages (lesson 6.10 measures right after each start)."""
from __future__ import annotations

import pytest
from labkit import observer
from labkit.rates import QUEUE_DEPTH, matching_qos, wait_for_publishers
from rclpy.qos import ReliabilityPolicy

from tests.tools.test_labkit_rates import HANG_GUARD, Talker

pytestmark = pytest.mark.ros  # publishes and subscribes on a ROS graph


def test_waits_until_a_new_publisher_is_discovered():
    node = observer.observer().node
    talker = Talker('/rates_discovery', ReliabilityPolicy.RELIABLE, 'x')
    try:
        # No waiting here: the publisher was created a moment ago.
        assert wait_for_publishers(node, ['/rates_discovery'], HANG_GUARD)
        qos = matching_qos(node, '/rates_discovery')
        assert qos.reliability == ReliabilityPolicy.RELIABLE
        assert qos.depth == QUEUE_DEPTH
    finally:
        talker.close()


def test_gives_up_on_a_topic_nobody_publishes():
    assert not wait_for_publishers(observer.observer().node, ['/rates_nobody_at_all'], 0.5)
