"""A snapshot of the running ROS graph and a node's parameters, read with rclpy only.

What `ros2 node list` / `ros2 topic info` show, as data a check can compare
with a spec: nodes, topics with their types, who publishes and who
subscribes.  Hidden nodes (the observer's own, ros2cli's) and the topics every
node has (/rosout, /parameter_events) are left out by default, like
rqt_graph's "Hide" options.  labkit's `labkit.graph()` is this snapshot with a
drawing added.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from rcl_interfaces.srv import GetParameters, ListParameters
from rclhelpers.names import is_hidden
from rclpy.parameter import parameter_value_to_python

from speccheck import observer
from speccheck.ros_error import RosError

#: Topics every node publishes or subscribes to; noise in a picture of a system.
DEFAULT_TOPICS = ('/rosout', '/parameter_events')
#: What a node that does not answer its parameter services probably means.
NOT_RUNNING_HINT = 'is the node running?'


@dataclass(frozen=True)
class Topic:
    """One topic: its name, message type(s) and the nodes on each side."""

    name: str
    types: tuple[str, ...]
    publishers: tuple[str, ...]
    subscribers: tuple[str, ...]

    @property
    def type(self) -> str:
        """The message type (types joined with ', ' in the rare mixed case)."""
        return ', '.join(self.types)


@dataclass(frozen=True)
class GraphSnapshot:
    """The ROS graph at one moment.

    Attributes:
        nodes: full node names, sorted.
        topics: topic name -> :class:`Topic`, sorted by name.
        services: service name -> service types (hidden services left out).
    """

    nodes: tuple[str, ...]
    topics: dict[str, Topic]
    services: dict[str, tuple[str, ...]] = field(default_factory=dict)

    def publishers(self, topic: str) -> tuple[str, ...]:
        """Nodes publishing on `topic`."""
        return self.topics[topic].publishers

    def subscribers(self, topic: str) -> tuple[str, ...]:
        """Nodes subscribed to `topic`."""
        return self.topics[topic].subscribers

    def edges(self) -> list[tuple[str, str]]:
        """(from, to) pairs, node -> topic -> node, as rqt_graph draws them."""
        pairs = []
        for topic in self.topics.values():
            pairs += [(node, topic.name) for node in topic.publishers]
            pairs += [(topic.name, node) for node in topic.subscribers]
        return pairs

    def parameters(self, node: str) -> dict[str, Any]:
        """The parameters of a running node, name -> value, read from its services."""
        return read_parameters(node)

    def __str__(self) -> str:
        lines = [f'{len(self.nodes)} nodes: {", ".join(self.nodes) or "none"}']
        for topic in self.topics.values():
            lines.append(f'{topic.name} [{topic.type}]')
            lines.append(f'    published by: {", ".join(topic.publishers) or "nobody"}')
            lines.append(f'    subscribed by: {", ".join(topic.subscribers) or "nobody"}')
        return '\n'.join(lines)

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:  # IPython display
        printer.text(str(self))


def graph(include_hidden: bool = False, include_default_topics: bool = False) -> GraphSnapshot:
    """Look at the ROS graph now and return what is in it.

    The first call in a process takes a few seconds (discovery has to find
    everything); later calls are quick.
    """
    observer.settle()
    node = observer.observer().node
    endpoints = observer.topic_endpoints(node)
    visible = {name for name in observer.live_node_names(node, endpoints)
               if include_hidden or not is_hidden(name)}
    topics = {}
    for topic, (types, publishers, subscribers) in sorted(endpoints.items()):
        if not include_hidden and is_hidden(topic):
            continue
        if not include_default_topics and topic in DEFAULT_TOPICS:
            continue
        pubs = sorted(name for name in publishers if name in visible)
        subs = sorted(name for name in subscribers if name in visible)
        if not pubs and not subs:
            continue  # only hidden nodes use it
        topics[topic] = Topic(topic, tuple(types), tuple(pubs), tuple(subs))
    services = {service: tuple(types)
                for service, types in sorted(node.get_service_names_and_types())
                if include_hidden or not is_hidden(service)}
    return GraphSnapshot(tuple(sorted(visible)), topics, services)


def read_parameters(node: str, timeout: float = 5.0,
                    hint: str = NOT_RUNNING_HINT) -> dict[str, Any]:
    """Parameters of `node` (e.g. '/robot_controller'), sorted by name.

    Values as rclpy's `parameter_value_to_python` gives them (arrays as lists,
    unset as None), so they compare with what a node declared.

    Raises RosError when the node does not answer its parameter services; the
    message ends with `hint` when it does not answer at all.
    """
    target = node if node.startswith('/') else '/' + node
    obs = observer.observer()
    listing = obs.read(ListParameters, f'{target}/list_parameters',
                       ListParameters.Request(depth=0), timeout)
    if listing is None:
        raise RosError(f'{target} did not answer on {target}/list_parameters: {hint}')
    names = sorted(listing.result.names)
    values = obs.read(GetParameters, f'{target}/get_parameters',
                      GetParameters.Request(names=names), timeout)
    if values is None:
        raise RosError(f'{target} did not answer on {target}/get_parameters')
    return {name: parameter_value_to_python(value)
            for name, value in zip(names, values.values, strict=True)}
