"""Service calls from a node that nothing spins."""
from __future__ import annotations

import time
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


#: Seconds a read waits for an answer before it asks again.
RESEND_AFTER = 1.0


def read_service(node: Node, srv_type: Any, name: str, request: Any,
                 timeout: float = 5.0) -> Any | None:
    """:func:`call_service` for a request that may be repeated (a read), asked again
    every RESEND_AFTER seconds until answered or ``timeout`` has passed.

    A node that was killed stays discovered until its DDS lease ends.  When a new
    node of the same name starts, a client may first match only the old server:
    the request goes there and is never answered.  Asking again reaches the new
    server once it is discovered.
    """
    deadline = time.monotonic() + timeout
    while (remaining := deadline - time.monotonic()) > 0:
        response = call_service(node, srv_type, name, request, min(remaining, RESEND_AFTER))
        if response is not None:
            return response
    return None
