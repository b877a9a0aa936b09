"""`labkit.graph()`: a snapshot of the running ROS graph, read with rclpy only.

What rqt_graph shows, as data a lesson can print or assert on: nodes,
topics with their types, who publishes and who subscribes.  Hidden nodes
(labkit's own, ros2cli's) and the topics every node has (/rosout,
/parameter_events) are left out by default, like rqt_graph's "Hide" options.
The reading is speccheck's (`speccheck.graph`, one copy for both tools);
labkit adds the drawing and raises LabkitError.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from speccheck import graph as shared
from speccheck.graph import DEFAULT_TOPICS, Topic

from labkit.errors import as_labkit_error
from labkit.graph_drawing import render

__all__ = ['DEFAULT_TOPICS', 'GraphSnapshot', 'Topic', 'graph', 'read_parameters']


@dataclass(frozen=True)
class GraphSnapshot(shared.GraphSnapshot):
    """The ROS graph at one moment (see :class:`speccheck.graph.GraphSnapshot`),
    which draws itself as rqt_graph would.

    Attributes:
        nodes: full node names, sorted.
        topics: topic name -> :class:`Topic`, sorted by name.
        services: service name -> service types (hidden services left out).
    """

    def parameters(self, node: str) -> dict[str, Any]:
        """The parameters of a running node, name -> value, read from its services."""
        return read_parameters(node)

    def draw(self, **options: Any) -> Any:
        """The graph as a matplotlib Figure (see :func:`labkit.draw_graph`)."""
        return render(self, **options)


def graph(include_hidden: bool = False, include_default_topics: bool = False) -> GraphSnapshot:
    """Look at the ROS graph now and return what is in it.

    The first call in a kernel takes a few seconds (discovery has to find
    everything); later calls are quick.
    """
    seen = shared.graph(include_hidden, include_default_topics)
    return GraphSnapshot(seen.nodes, seen.topics, seen.services)


def read_parameters(node: str, timeout: float = 5.0) -> dict[str, Any]:
    """Parameters of `node` (e.g. '/robot_controller'), sorted by name.

    Values as rclpy's `parameter_value_to_python` gives them (arrays as lists,
    unset as None), so they compare with what a node declared.

    Raises LabkitError when the node does not answer its parameter services.
    """
    with as_labkit_error():
        return shared.read_parameters(
            node, timeout, hint='is the node running (see labkit.graph().nodes)?')
