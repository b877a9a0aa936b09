"""The actions in the graph, read from the topics and endpoints that make them up.

An action `/x` is a feedback topic `/x/_action/feedback` of type
`pkg/action/T_FeedbackMessage` (and four more endpoints), so its name and
type follow from the topic list; that works against the daemon's graph and
a command's own node alike.
"""
from __future__ import annotations

from typing import Any

from rclhelpers.names import full_name
from rclpy.action.graph import (
    get_action_client_names_and_types_by_node,
    get_action_server_names_and_types_by_node,
)

FEEDBACK_SUFFIX = '/_action/feedback'
FEEDBACK_TYPE_SUFFIX = '_FeedbackMessage'


def action_names_and_types(graph: Any) -> list[tuple[str, list[str]]]:
    """Every action in the graph (hidden ones too) with its types, sorted by name."""
    actions = {}
    for topic, types in graph.get_topic_names_and_types():
        if topic.endswith(FEEDBACK_SUFFIX):
            actions[topic[:-len(FEEDBACK_SUFFIX)]] = [
                kind.removesuffix(FEEDBACK_TYPE_SUFFIX) for kind in types]
    return sorted(actions.items())


def _by_node(graph: Any, method: str) -> Any:
    """The daemon answers the by-node action queries itself; a node goes through rclpy."""
    query = getattr(graph, method, None)
    if query is not None:
        return query
    function = {'get_action_server_names_and_types_by_node':
                get_action_server_names_and_types_by_node,
                'get_action_client_names_and_types_by_node':
                get_action_client_names_and_types_by_node}[method]
    return lambda name, namespace: function(graph, name, namespace)


def action_endpoints(graph: Any, action: str) -> tuple[list[tuple[str, list[str]]],
                                                        list[tuple[str, list[str]]]]:
    """The (node, types) of the clients and of the servers of `action`, hidden nodes too."""
    sides: tuple[list, list] = ([], [])
    queries = (_by_node(graph, 'get_action_client_names_and_types_by_node'),
               _by_node(graph, 'get_action_server_names_and_types_by_node'))
    for name, namespace in sorted(graph.get_node_names_and_namespaces(),
                                  key=lambda item: full_name(item[0], item[1])):
        for side, query in zip(sides, queries, strict=True):
            try:
                entries = query(name, namespace)
            except Exception:  # noqa: BLE001 - the node may vanish meanwhile
                continue
            for entry_name, types in entries:
                if entry_name == action:
                    side.append((full_name(name, namespace), list(types)))
    return sides
