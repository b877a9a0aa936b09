"""How often messages arrive on topics, measured over a bounded window.

Like `ros2 topic hz`, but for several topics at once and returning numbers:
one subscription per topic on labkit's hidden observer node, best effort and
volatile so that it matches any publisher, kept for `window` seconds.
"""
from __future__ import annotations

import importlib
import time
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import qos_profile_sensor_data

from labkit import observer
from labkit.errors import LabkitError


@dataclass(frozen=True)
class Rate:
    """Messages seen on one topic during the window."""

    topic: str
    count: int
    window: float
    hz: float | None  # None with fewer than two messages

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
        raise LabkitError(f'cannot import the message type {type_name!r}') from None


def measure_rates(topics: Mapping[str, str], window: float = 3.0) -> dict[str, Rate]:
    """Rate of each topic (name -> message type name), all measured in one window."""
    obs = observer.observer()
    arrivals: dict[str, list[float]] = {topic: [] for topic in topics}
    subscriptions = []
    for topic, type_name in topics.items():
        stamps = arrivals[topic]
        subscriptions.append(obs.node.create_subscription(
            message_class(type_name), topic, lambda _msg, stamps=stamps:
            stamps.append(time.monotonic()), qos_profile_sensor_data, raw=True))
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
    return {topic: _rate(topic, stamps, window) for topic, stamps in arrivals.items()}


def _rate(topic: str, stamps: list[float], window: float) -> Rate:
    if len(stamps) < 2:
        return Rate(topic, len(stamps), window, None)
    return Rate(topic, len(stamps), window, (len(stamps) - 1) / (stamps[-1] - stamps[0]))
