"""One hidden rclpy node per process that watches the ROS graph.

Discovery takes seconds for a newcomer (Fast DDS answers a new participant
at its next announcement, every 3 s by default), so a single node stays
alive for the whole process (a `speccheck` run, or a notebook kernel through
labkit, which uses this module) instead of joining the graph for every
question: after the first look, the graph it sees is always current.

The node lives in its own rclpy Context with no signal handlers, so it
neither disturbs a student's own `rclpy.init()` in the same kernel nor
steals the notebook's Ctrl-C / interrupt.
"""
from __future__ import annotations

import atexit
import os
import threading
import time
from typing import Any

import rclpy
from rclhelpers.names import full_name, is_hidden
from rclhelpers.services import call_service, read_service
from rclpy.context import Context
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

#: How long a brand-new observer waits before trusting that it has seen the
#: whole graph: one Fast DDS announcement period and a margin.
FIRST_LOOK_WAIT = 3.6
#: Later looks only wait until the graph has been unchanged for this long.
QUIET_TIME = 0.3

#: Start of the observer's node name (hidden: a leading underscore); labkit sets
#: '_labkit' so that a lesson's hidden nodes say whose they are.
NODE_PREFIX = '_speccheck'

#: Node name the rmw gives an endpoint before its node is known.
UNKNOWN_NODE = '_NODE_NAME_UNKNOWN_'

_lock = threading.RLock()
_observer: Observer | None = None


class Observer:
    """The hidden node and its private context."""

    def __init__(self) -> None:
        self.context = Context()
        rclpy.init(args=[], context=self.context,
                   signal_handler_options=SignalHandlerOptions.NO)
        self.node: Node = rclpy.create_node(
            f'{NODE_PREFIX}_{os.getpid()}', context=self.context,
            start_parameter_services=False, enable_rosout=False)
        self.created = time.monotonic()

    def close(self) -> None:
        self.node.destroy_node()
        self.context.try_shutdown()

    def call(self, srv_type: Any, service: str, request: Any, timeout: float = 5.0) -> Any:
        """Call a service once from the observer's node; None if nobody answered."""
        return call_service(self.node, srv_type, service, request, timeout)

    def read(self, srv_type: Any, service: str, request: Any, timeout: float = 5.0) -> Any:
        """A read (asked again until answered, see rclhelpers.services.read_service)."""
        return read_service(self.node, srv_type, service, request, timeout)


def observer() -> Observer:
    """The process's observer, created on first use."""
    global _observer
    with _lock:
        if _observer is None:
            _observer = Observer()
        return _observer


@atexit.register
def close() -> None:
    """Leave the graph now (the next question makes a new observer, with a first look).

    For a process that is about to watch nothing for a while as other
    processes start and stop many nodes: an idle participant still processes
    every endpoint that goes away, which is where Fast DDS can deadlock its own
    discovery threads (eProsima/Fast-DDS#6502).
    """
    global _observer
    with _lock:
        if _observer is not None:
            _observer.close()
            _observer = None


def topic_endpoints(node: Node) -> dict[str, tuple[list[str], set[str], set[str]]]:
    """Every topic: its types, and the full names of its publishers and subscribers.

    Read endpoint by endpoint (`get_publishers_info_by_topic`), not node by
    node: a long-lived observer sometimes keeps a node that has exited in its
    node list for good (a discovery update racing the node's departure,
    ros2/ros2#514).  Such a leftover owns no endpoints, but it can shadow a
    live node of the same name in the by-node queries, which then report
    nothing for the live one.  Endpoints of exited nodes are always gone.
    """
    topics = {}
    for topic, types in node.get_topic_names_and_types():
        try:
            publishers = node.get_publishers_info_by_topic(topic)
            subscribers = node.get_subscriptions_info_by_topic(topic)
        except Exception:  # the topic went away between listing and asking
            continue
        topics[topic] = (types, _owners(publishers), _owners(subscribers))
    return topics


def _owners(endpoints: list[Any]) -> set[str]:
    """Full node names of endpoints whose node is known yet (a node's name
    arrives a moment after its first endpoints)."""
    return {full_name(info.node_name, info.node_namespace) for info in endpoints
            if info.node_name != UNKNOWN_NODE}


def _has_services(node: Node, name: str, namespace: str) -> bool:
    """Whether the node offers or calls a service (left-over nodes do neither)."""
    try:
        return bool(node.get_service_names_and_types_by_node(name, namespace)
                    or node.get_client_names_and_types_by_node(name, namespace))
    except Exception:  # the node left between listing and asking
        return False


def live_node_names(node: Node, topics: dict | None = None) -> set[str]:
    """Full names of the nodes that own a topic endpoint or a service, so
    without the left-overs of exited nodes (see :func:`topic_endpoints`)."""
    if topics is None:
        topics = topic_endpoints(node)
    names = {name for _, publishers, subscribers in topics.values()
             for name in publishers | subscribers}
    names |= {full_name(n, ns) for n, ns in node.get_node_names_and_namespaces()
              if full_name(n, ns) not in names and _has_services(node, n, ns)}
    return names


def node_names(include_hidden: bool = False) -> list[str]:
    """Full names of the nodes in the graph right now, sorted."""
    names = live_node_names(observer().node)
    return sorted(n for n in names if include_hidden or not is_hidden(n))


def _fingerprint(node: Node) -> tuple:
    """What the graph looks like now; endpoint counts too, because a second
    publisher on a topic that already exists changes no name or type."""
    topics = sorted((name, tuple(types)) for name, types in node.get_topic_names_and_types())
    return (sorted(node.get_node_names_and_namespaces()), topics,
            [(node.count_publishers(name), node.count_subscribers(name)) for name, _ in topics],
            sorted((name, tuple(types)) for name, types in node.get_service_names_and_types()))


def settle(max_wait: float = 6.0) -> None:
    """Wait until the graph the observer sees is complete and stable.

    The first call in a kernel waits a full discovery period; later calls
    only until nothing has changed for a moment.
    """
    obs = observer()
    start = time.monotonic()
    first_look_done = obs.created + FIRST_LOOK_WAIT
    last, last_change = None, start
    while True:
        now = time.monotonic()
        current = _fingerprint(obs.node)
        if current != last:
            last, last_change = current, now
        if now >= first_look_done and now - last_change >= QUIET_TIME:
            return
        if now - start >= max_wait:
            return
        time.sleep(0.05)
