"""WaitForTopics: wait until messages arrived on every one of some topics.

It uses its own rclpy context, node and executor thread, so it works whether
or not the test called rclpy.init() itself.
"""
from __future__ import annotations

import collections
import threading
import uuid
from collections.abc import Callable, Iterable

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


class WaitForTopics:
    """Wait to receive messages on the given (topic name, message type) pairs.

        with WaitForTopics([('chatter', String)], timeout=5.0):
            ...  # each topic received at least one message

    or `w = WaitForTopics(...); assert w.wait(); ...; w.shutdown()`.
    """

    def __init__(self, topic_tuples: Iterable[tuple[str, type]], timeout: float = 5.0,
                 messages_received_buffer_length: int = 10,
                 trigger: Callable | None = None, node_namespace: str | None = None,
                 qos_profile=10) -> None:
        self.topic_tuples = list(topic_tuples)
        self.timeout = timeout
        self.trigger = trigger
        self.node_namespace = node_namespace
        self._qos_profile = qos_profile
        self._buffer_length = messages_received_buffer_length
        self._lock = threading.Lock()
        self._all_received = threading.Event()
        self._received: dict[str, collections.deque] = {}
        self._expected: set[str] = {name for name, _ in self.topic_tuples}
        self._context: rclpy.Context | None = None
        self._node: Node | None = None
        self._executor: SingleThreadedExecutor | None = None
        self._thread: threading.Thread | None = None

    def _start(self) -> None:
        self._context = rclpy.Context()
        self._context.init()
        kwargs = {'context': self._context}
        if self.node_namespace:
            kwargs['namespace'] = self.node_namespace
        self._node = Node(f'_wait_for_topics_{uuid.uuid4().hex[:12]}', **kwargs)
        for name, message_type in self.topic_tuples:
            self._node.create_subscription(message_type, name, self._callback_for(name),
                                           self._qos_profile)
        self._executor = SingleThreadedExecutor(context=self._context)
        self._executor.add_node(self._node)
        self._thread = threading.Thread(target=self._spin, name='wait_for_topics', daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        try:
            self._executor.spin()
        except Exception:  # noqa: BLE001 - the context was shut down under the executor
            pass

    def _callback_for(self, name: str) -> Callable:
        def callback(message) -> None:
            with self._lock:
                buffer = self._received.setdefault(
                    name, collections.deque(maxlen=self._buffer_length))
                buffer.append(message)
                if self._expected.issubset(self._received):
                    self._all_received.set()
        return callback

    def wait(self, *args, **kwargs) -> bool:
        """Subscribe, call the trigger (if any), and wait; True when every topic got one."""
        if self._node is None:
            self._start()
        if self.trigger is not None:
            self.trigger(self._node, *args, **kwargs)
        return self._all_received.wait(self.timeout)

    def shutdown(self) -> None:
        """Stop the node and its executor thread."""
        if self._executor is not None:
            self._executor.shutdown()
        if self._node is not None:
            self._node.destroy_node()
        if self._context is not None:
            self._context.try_shutdown()
        if self._thread is not None:
            self._thread.join(5.0)
        self._executor = self._node = self._context = self._thread = None

    def topics_received(self) -> set[str]:
        """Topics that received at least one message."""
        with self._lock:
            return set(self._received)

    def topics_not_received(self) -> set[str]:
        """Topics that did not receive any message."""
        return self._expected - self.topics_received()

    def received_messages(self, topic_name: str) -> list:
        """The last messages (up to the buffer length) received on a topic."""
        if topic_name not in self._expected:
            raise KeyError(f"'{topic_name}' is not one of the topics being waited for")
        with self._lock:
            return list(self._received.get(topic_name, ()))

    messages_received = received_messages

    def __enter__(self) -> WaitForTopics:
        if not self.wait():
            missing = self.topics_not_received()
            self.shutdown()
            # Jazzy's error: a tuple of the text and the set of topic names
            raise RuntimeError('Did not receive messages on these topics: ', missing)
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.shutdown()
