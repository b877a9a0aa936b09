"""One service call on a node that nothing spins."""
from __future__ import annotations

from typing import Any

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


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
