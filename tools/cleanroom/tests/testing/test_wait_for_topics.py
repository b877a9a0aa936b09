"""launch_testing_ros.WaitForTopics: received and missing topics, with and without `with`."""
from __future__ import annotations

import threading
import uuid

import pytest
import rclpy
from launch_testing_ros import WaitForTopics
from rclpy.executors import SingleThreadedExecutor
from std_msgs.msg import String


@pytest.fixture
def publisher(ros_domain):
    """A node in its own context publishing 'hi N' on a fresh topic every 50 ms."""
    context = rclpy.Context()
    context.init()
    node = rclpy.create_node(f'publisher_{uuid.uuid4().hex[:8]}', context=context)
    topic = f'chatter_{uuid.uuid4().hex[:8]}'
    pub = node.create_publisher(String, topic, 10)
    count = [0]

    def tick():
        pub.publish(String(data=f'hi {count[0]}'))
        count[0] += 1

    node.create_timer(0.05, tick)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    thread = threading.Thread(target=executor.spin, daemon=True)
    thread.start()
    yield topic
    executor.shutdown()
    node.destroy_node()
    context.try_shutdown()
    thread.join(5)


def test_with_block_sees_messages(publisher):
    with WaitForTopics([(publisher, String)], timeout=20.0,
                       messages_received_buffer_length=3) as waiter:
        assert waiter.topics_received() == {publisher}
        assert waiter.topics_not_received() == set()
        messages = waiter.received_messages(publisher)
        assert 1 <= len(messages) <= 3
        assert all(m.data.startswith('hi ') for m in messages)


def test_missing_topic_times_out(publisher):
    missing = f'nobody_{uuid.uuid4().hex[:8]}'
    waiter = WaitForTopics([(publisher, String), (missing, String)], timeout=1.0)
    try:
        assert waiter.wait() is False
        assert waiter.topics_not_received() == {missing}
        assert waiter.received_messages(missing) == []
    finally:
        waiter.shutdown()


def test_with_block_raises_naming_the_missing_topic(ros_domain):
    missing = f'nobody_{uuid.uuid4().hex[:8]}'
    with pytest.raises(RuntimeError, match=missing):
        with WaitForTopics([(missing, String)], timeout=0.5):
            pass


def test_trigger_gets_the_node_and_arguments(publisher):
    seen = []
    waiter = WaitForTopics([(publisher, String)], timeout=20.0,
                           trigger=lambda node, word: seen.append((node.get_name(), word)))
    try:
        assert waiter.wait('go')
        assert seen and seen[0][1] == 'go'
    finally:
        waiter.shutdown()
