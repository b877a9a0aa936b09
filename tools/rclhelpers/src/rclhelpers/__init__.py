"""rclpy helpers shared by labkit and the clean room's `ros2`; imports only rclpy.

labkit must run on a real ROS 2, where the clean room is not installed, and
the clean room (our stand-in for ROS 2's launch and ros2cli) may not import
labkit: this distribution is the bottom layer both can use (issue 13).
"""
from __future__ import annotations

from typing import Any

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

__all__ = ['call_service', 'full_name', 'is_hidden', 'split_full_name']


def full_name(name: str, namespace: str) -> str:
    """`/ns` + `name` -> `/ns/name` (the root namespace gives `/name`).

    rclpy's graph queries give a node's name and namespace apart; listings
    and lookups use the one full name.
    """
    return namespace.rstrip('/') + '/' + name


def split_full_name(full: str) -> tuple[str, str]:
    """`/ns/name` -> (`name`, `/ns`); a name without a slash is in `/`.

    The reverse of :func:`full_name`, for rclpy's by-node queries.
    """
    full = full if full.startswith('/') else '/' + full
    namespace, _, name = full.rpartition('/')
    return name, namespace or '/'


def is_hidden(name: str) -> bool:
    """ROS hides any node, topic or service with a name token starting with `_`.

    That is how labkit's observer and the `ros2` command's own node stay out
    of the listings they make.
    """
    return any(token.startswith('_') for token in name.split('/') if token)


def call_service(node: Node, srv_type: Any, name: str, request: Any,
                 timeout: float = 5.0) -> Any | None:
    """Call a service once and return its response, or None if nobody answered.

    Nothing spins `node` in the background, so rclpy's `Client.call()`
    (which waits for another thread's executor) would only time out: the
    call is spun here, on a temporary executor in the node's own context,
    with rclpy's own helpers.  `timeout` bounds the wait for the service and
    then the wait for the answer.
    """
    client = node.create_client(srv_type, name)
    try:
        if not client.wait_for_service(timeout_sec=timeout):
            return None
        future = client.call_async(request)
        with SingleThreadedExecutor(context=node.context) as executor:
            rclpy.spin_until_future_complete(node, future, executor=executor,
                                             timeout_sec=timeout)
        return future.result() if future.done() else None
    finally:
        node.destroy_client(client)
