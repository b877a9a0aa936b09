"""What `ros2 doctor` finds in the running graph: lonely endpoints and QoS mismatches.

Kept apart from the verb's printing so the findings can be tested on plain
endpoint lists.  The graph is read once (a snapshot) after discovery settled.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from rclpy.node import Node
from rclpy.qos import QoSCompatibility, qos_check_compatible

#: Every node has these; Jazzy's doctor leaves them out of its topic checks and report.
IGNORED_TOPICS = ('/parameter_events', '/rosout')


@dataclass
class TopicEndpoints:
    """One topic with the publishers and subscriptions of the other nodes on it."""

    name: str
    types: list[str]
    publishers: list[Any] = field(default_factory=list)  # rclpy TopicEndpointInfo
    subscribers: list[Any] = field(default_factory=list)


@dataclass
class QosPair:
    """One publisher/subscription pair of a topic and whether their QoS match."""

    topic: str
    types: list[str]
    publisher_node: str
    subscriber_node: str
    compatibility: QoSCompatibility
    reason: str

    @property
    def status(self) -> str:
        """`OK`, or rmw's reason, e.g. `ERROR: Best effort publisher and reliable subscription;`."""
        return 'OK' if self.compatibility == QoSCompatibility.OK else self.reason


def snapshot(node: Node) -> list[TopicEndpoints]:
    """The topics of the graph (sorted), without `node`'s own endpoints."""
    own = (node.get_name(), node.get_namespace())
    topics = []
    for name, types in sorted(node.get_topic_names_and_types()):
        if name in IGNORED_TOPICS:
            continue
        topics.append(TopicEndpoints(
            name, list(types),
            [i for i in node.get_publishers_info_by_topic(name)
             if (i.node_name, i.node_namespace) != own],
            [i for i in node.get_subscriptions_info_by_topic(name)
             if (i.node_name, i.node_namespace) != own]))
    return topics


def lonely_endpoint_warnings(topics: list[TopicEndpoints]) -> list[str]:
    """The topic check: a publisher nobody listens to, or a subscription nobody feeds."""
    warnings = []
    for topic in topics:
        if topic.publishers and not topic.subscribers:
            warnings.append(f'Publisher without subscriber detected on {topic.name}.')
        elif topic.subscribers and not topic.publishers:
            warnings.append(f'Subscriber without publisher detected on {topic.name}.')
    return warnings


def qos_pairs(topics: list[TopicEndpoints]) -> list[QosPair]:
    """Every publisher x subscription pair of every topic, checked by rmw's rules."""
    pairs = []
    for topic in topics:
        for publisher in topic.publishers:
            for subscriber in topic.subscribers:
                compatibility, reason = qos_check_compatible(
                    publisher.qos_profile, subscriber.qos_profile)
                # Jazzy names the publisher's type, not every type of the topic
                pairs.append(QosPair(topic.name, [publisher.topic_type], publisher.node_name,
                                     subscriber.node_name, compatibility, reason))
    return pairs


def qos_errors(pairs: list[QosPair]) -> list[str]:
    """The QoS check: one error per incompatible pair (a reliable reader of a
    best-effort writer receives nothing)."""
    errors = []
    for pair in pairs:
        if pair.compatibility == QoSCompatibility.ERROR:
            reason = pair.reason.removeprefix('ERROR: ')
            errors.append(f"ERROR: QoS compatibility error found on topic '{pair.topic}': "
                          f'{reason}')
    return errors
