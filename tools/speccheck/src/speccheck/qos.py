"""QoS of every publisher and subscriber of a topic, and which pairs cannot talk.

A subscriber whose QoS asks for more than a publisher offers (reliable from a
best-effort publisher, transient-local from a volatile one) never receives
anything, and nothing in the graph says so: `ros2 topic info -v` shows the
profiles, and this module pairs them up with rclpy's own compatibility rule.
"""
from __future__ import annotations

from dataclasses import dataclass

from rclhelpers.names import full_name, is_hidden
from rclpy.qos import QoSCompatibility, QoSProfile, qos_check_compatible

from speccheck import observer


@dataclass(frozen=True)
class Endpoint:
    """One publisher or subscriber of a topic."""

    node: str
    qos: QoSProfile

    @property
    def reliability(self) -> str:
        return self.qos.reliability.name.lower()

    @property
    def durability(self) -> str:
        return self.qos.durability.name.lower()

    def describe(self) -> str:
        return f'{self.node} ({self.reliability}, {self.durability})'


@dataclass(frozen=True)
class Mismatch:
    """A publisher/subscriber pair whose QoS does not match (or only with a warning)."""

    publisher: Endpoint
    subscriber: Endpoint
    error: bool
    reason: str


def endpoints(topic: str) -> tuple[list[Endpoint], list[Endpoint]]:
    """(publishers, subscribers) of `topic` with their QoS, hidden nodes left out."""
    observer.settle()
    node = observer.observer().node
    return (_visible(node.get_publishers_info_by_topic(topic)),
            _visible(node.get_subscriptions_info_by_topic(topic)))


def _visible(infos: list) -> list[Endpoint]:
    found = [Endpoint(full_name(info.node_name, info.node_namespace), info.qos_profile)
             for info in infos if info.node_name != observer.UNKNOWN_NODE]
    return sorted((e for e in found if not is_hidden(e.node)), key=lambda e: e.node)


def mismatches(topic: str) -> list[Mismatch]:
    """Every publisher/subscriber pair of `topic` that rclpy does not call compatible."""
    publishers, subscribers = endpoints(topic)
    found = []
    for publisher in publishers:
        for subscriber in subscribers:
            compatibility, reason = qos_check_compatible(publisher.qos, subscriber.qos)
            if compatibility != QoSCompatibility.OK:
                found.append(Mismatch(publisher, subscriber,
                                      compatibility == QoSCompatibility.ERROR, reason))
    return found
