"""Lifecycle nodes in the graph, and the calls to the services each one offers.

A lifecycle node is one that serves `<node>/get_state` (lifecycle_msgs
GetState); its state and transitions are asked over its own services.
"""
from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any

from lifecycle_msgs.msg import Transition
from lifecycle_msgs.srv import ChangeState, GetAvailableTransitions, GetState
from rclhelpers.names import full_name, is_hidden
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

from ros2_cleanroom import cli_node

GET_STATE_TYPE = 'lifecycle_msgs/srv/GetState'


def lifecycle_nodes(graph: Any, include_hidden: bool) -> list[str]:
    """Full names of the nodes serving a lifecycle GetState service, sorted."""
    names = []
    for name, namespace in graph.get_node_names_and_namespaces():
        node = full_name(name, namespace)
        if not include_hidden and is_hidden(node):
            continue
        try:
            services = graph.get_service_names_and_types_by_node(name, namespace)
        except Exception:  # noqa: BLE001 - the node may vanish meanwhile
            continue
        if any(service == node + '/get_state' and GET_STATE_TYPE in types
               for service, types in services):
            names.append(node)
    return sorted(names)


@contextlib.contextmanager
def caller(graph: Any) -> Iterator[Node]:
    """A node to call services with: the command's own, unless the daemon answered."""
    if isinstance(graph, Node):
        yield graph
        return
    with cli_node.cli_node() as node:
        yield node


def call(node: Node, srv_type: type, service: str, request: Any) -> Any:
    """Call `service` once it is there, and wait for its answer (Ctrl-C ends it)."""
    client = node.create_client(srv_type, service)
    try:
        while not client.wait_for_service(timeout_sec=1.0):
            pass
        future = client.call_async(request)
        executor = SingleThreadedExecutor(context=node.context)
        executor.add_node(node)
        while not future.done():
            executor.spin_once(timeout_sec=0.1)
        executor.remove_node(node)
        return future.result()
    finally:
        node.destroy_client(client)


def get_state(node: Node, target: str) -> Any:
    """The node's current state (lifecycle_msgs State: id and label)."""
    return call(node, GetState, target + '/get_state', GetState.Request()).current_state


def transitions(node: Node, target: str, graph: bool = False) -> list[Any]:
    """The transitions available from the node's state, or (`graph`) all of them."""
    service = target + ('/get_transition_graph' if graph else '/get_available_transitions')
    return list(call(node, GetAvailableTransitions, service,
                     GetAvailableTransitions.Request()).available_transitions)


def change_state(node: Node, target: str, transition: Any) -> bool:
    """Trigger `transition` (a lifecycle_msgs Transition); True if it succeeded."""
    request = ChangeState.Request(
        transition=Transition(id=transition.id, label=transition.label))
    return call(node, ChangeState, target + '/change_state', request).success
