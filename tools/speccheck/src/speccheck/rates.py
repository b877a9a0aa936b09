"""How often messages arrive on topics, and how large they are, measured over
a bounded window.

Like `ros2 topic hz`, but for several topics at once and returning numbers:
one subscription per topic on the hidden observer node (`speccheck.observer`), kept for
`window` seconds.  Like `ros2 topic hz`, it is reliable when every publisher
of the topic is (a large message sent best effort loses fragments, and a
whole frame with each; measured on 2.7 MB images: 3-10 of 30 per second
arrived best effort, 24 reliable), otherwise best effort; always volatile,
so that it matches any publisher.  A topic whose publisher was started
a moment ago may not be discovered yet; the reliability is chosen once it is
(or after `discovery` seconds, for a topic nobody publishes).  The
subscriptions take messages serialized (never converted to Python), so the
size of each is known for free: the bytes that cross the middleware.

Each message is timed by when it was published (its message info's source
timestamp), not by when this process got round to it: on a loaded machine
the measuring executor falls behind, takes the queued messages in a burst and
leaves the last ones for after the window, and a rate timed on arrival made
the publisher look slow (a 10 Hz sensor measured 6.5 Hz in a loaded CI run).
"""
from __future__ import annotations

import functools
import importlib
import time
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy

from speccheck import observer
from speccheck.ros_error import RosError


@dataclass(frozen=True)
class Rate:
    """Messages seen on one topic during the window."""

    topic: str
    count: int
    window: float
    hz: float | None  # None with fewer than two messages
    size: float | None = None  # mean serialized bytes per message; None without messages

    @property
    def bytes_per_second(self) -> float | None:
        """What the topic costs the middleware: rate times message size."""
        return None if self.hz is None or self.size is None else self.hz * self.size

    def __str__(self) -> str:
        if self.hz is None:
            return f'{self.topic}: {self.count} message(s) in {self.window:g} s, no rate'
        return f'{self.topic}: {self.hz:.2f} Hz ({self.count} messages in {self.window:g} s)'


def message_class(type_name: str) -> Any:
    """'std_msgs/msg/Float32' -> the std_msgs.msg.Float32 class."""
    try:
        package, kind, name = type_name.split('/')
        return getattr(importlib.import_module(f'{package}.{kind}'), name)
    except (ValueError, ImportError, AttributeError):
        raise RosError(f'cannot import the message type {type_name!r}') from None


def measure_rates(topics: Mapping[str, str], window: float = 3.0,
                  discovery: float = 5.0) -> dict[str, Rate]:
    """Rate and mean message size of each topic (name -> message type name),
    all measured in one window.

    Waits up to `discovery` seconds for every topic to have a publisher in
    the graph first: a reliable publisher not yet discovered would get a best
    effort subscription, which loses large messages.
    """
    obs = observer.observer()
    wait_for_publishers(obs.node, topics, discovery)
    arrivals: dict[str, list[tuple[float, int]]] = {topic: [] for topic in topics}
    subscriptions = []
    for topic, type_name in topics.items():
        seen = arrivals[topic]
        subscriptions.append(obs.node.create_subscription(
            message_class(type_name), topic, functools.partial(_arrived, seen),
            matching_qos(obs.node, topic), raw=True))
    executor = SingleThreadedExecutor(context=obs.context)
    executor.add_node(obs.node)
    try:
        deadline = time.monotonic() + window
        while (remaining := deadline - time.monotonic()) > 0:
            executor.spin_once(timeout_sec=min(remaining, 0.1))
    finally:
        executor.remove_node(obs.node)
        executor.shutdown()
        for subscription in subscriptions:
            obs.node.destroy_subscription(subscription)
    return {topic: _rate(topic, seen, window) for topic, seen in arrivals.items()}


def _arrived(seen: list[tuple[float, int]], raw: bytes, info: Mapping[str, int]) -> None:
    """Record a message: when it was published (seconds) and its serialized size."""
    stamp = info['source_timestamp'] or info['received_timestamp']  # ns; 0 if not known
    seen.append((stamp / 1e9, len(raw)))


def wait_for_publishers(node: Node, topics: Iterable[str], timeout: float) -> bool:
    """Poll the graph until every topic has a publisher; False if `timeout` ran out."""
    deadline = time.monotonic() + timeout
    while not all(node.get_publishers_info_by_topic(topic) for topic in topics):
        if time.monotonic() >= deadline:
            return False
        time.sleep(0.05)
    return True


#: Messages a measuring subscription queues while the executor catches up.
#: With 10, a notebook took 64-100 % of 2.7 MB frames sent reliably at 30 fps
#: (the queue overflowed during short stalls); with 50, all of them.
QUEUE_DEPTH = 50


def matching_qos(node: Node, topic: str) -> QoSProfile:
    """Reliable if every publisher seen offers it, else best effort (volatile both)."""
    offered = [info.qos_profile.reliability for info in node.get_publishers_info_by_topic(topic)]
    reliable = bool(offered) and all(r == ReliabilityPolicy.RELIABLE for r in offered)
    return QoSProfile(depth=QUEUE_DEPTH, reliability=ReliabilityPolicy.RELIABLE if reliable
                      else ReliabilityPolicy.BEST_EFFORT)


def _rate(topic: str, seen: list[tuple[float, int]], window: float) -> Rate:
    size = sum(length for _, length in seen) / len(seen) if seen else None
    stamps = sorted(stamp for stamp, _ in seen)
    if len(seen) < 2 or stamps[-1] == stamps[0]:
        return Rate(topic, len(seen), window, None, size)
    hz = (len(seen) - 1) / (stamps[-1] - stamps[0])
    return Rate(topic, len(seen), window, hz, size)
