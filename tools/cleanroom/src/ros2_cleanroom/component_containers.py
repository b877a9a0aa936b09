"""Component containers in the graph and the services they offer.

A container is a node that offers `<its full name>/_container/list_nodes`
(composition_interfaces/srv/ListNodes), with `load_node` and `unload_node`
beside it.  composition_interfaces is imported only when a service is called:
listing and finding containers needs only the graph.
"""
from __future__ import annotations

import importlib
from types import ModuleType
from typing import Any

from rclhelpers.names import full_name
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

LIST_NODES_TYPE = 'composition_interfaces/srv/ListNodes'


def container_names(graph: Any) -> list[str]:
    """Full names of the container nodes, in the graph's order."""
    names = []
    for name, namespace in graph.get_node_names_and_namespaces():
        node = full_name(name, namespace)
        try:
            services = graph.get_service_names_and_types_by_node(name, namespace)
        except Exception:  # noqa: BLE001 - the node may vanish meanwhile
            continue
        if any(service == f'{node}/_container/list_nodes' and LIST_NODES_TYPE in types
               for service, types in services):
            names.append(node)
    return names


def service_types() -> ModuleType:
    """composition_interfaces.srv, imported when first needed: the PyPI wheels lack
    it, and `types`, `standalone` and the errors about missing containers do not
    need it (a sourced ROS 2 or workspace provides it)."""
    return importlib.import_module('composition_interfaces.srv')


def call(node: Node, srv_type: type, service: str, request: Any) -> Any:
    """Call a container's service and wait for the answer (Ctrl-C ends the wait)."""
    client = node.create_client(srv_type, service)
    while not client.wait_for_service(timeout_sec=1.0):
        pass
    return wait_for(node, client.call_async(request))


def wait_for(node: Node, future: Any) -> Any:
    """Spin `node` until `future` is done; its result."""
    executor = SingleThreadedExecutor(context=node.context)
    executor.add_node(node)
    while not future.done():
        executor.spin_once(timeout_sec=0.1)
    return future.result()


def list_components(node: Node, container: str) -> list[tuple[int, str]]:
    """(unique id, full node name) of every component loaded in `container`."""
    ListNodes = service_types().ListNodes  # noqa: N806 - the interface's own name
    response = call(node, ListNodes, f'{container}/_container/list_nodes', ListNodes.Request())
    return list(zip(response.unique_ids, response.full_node_names, strict=False))
