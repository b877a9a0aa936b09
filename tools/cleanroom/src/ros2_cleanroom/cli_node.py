"""The short-lived rclpy node every introspection verb works through.

A command that lists or describes the graph asks the ROS 2 daemon when one
is running (ros2_cleanroom.daemon): it answers at once with what it has
seen.  Without one, the command starts one for the next command and joins
the ROS graph itself, waits for discovery to settle and then answers.  Its
node is hidden (its name starts with `_`) so that it never shows up in the
listings it prints.
"""
from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Callable, Iterator

import rclpy
from rclhelpers.names import full_name, is_hidden
from rclpy.context import Context
from rclpy.node import Node

from ros2_cleanroom import daemon

# How long discovery takes.  Measured with Fast DDS and
# ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST: a new participant often hears from
# the others within 0.2 s, but as often only at their next periodic
# announcement, which comes every 3 s by default (seen: up to 3.4 s).  A graph
# that has looked stable for a second can therefore still be missing whole
# launches, so commands that list the whole graph wait one announcement
# period; commands about one node or topic stop as soon as it has shown up.

#: Minimum wait (seconds) before a listing of the whole graph is trusted.
MIN_WAIT = 3.6
#: The graph counts as settled when it has not changed for this long.
QUIET_TIME = 0.3
#: Upper bound for waiting on discovery (an absent node or topic costs this).
MAX_WAIT = 4.5
POLL = 0.05


@contextlib.contextmanager
def cli_node(prefix: str = '_ros2cli') -> Iterator[Node]:
    """Yield a hidden node in a private context, torn down on exit.

    A private context keeps the verb independent of any global rclpy state and
    makes shutdown deterministic even when the verb is left by an exception
    or Ctrl-C.
    """
    context = Context()
    rclpy.init(args=[], context=context)
    node = None
    try:
        node = rclpy.create_node(
            f'{prefix}_{os.getpid()}', context=context,
            start_parameter_services=False, enable_rosout=False)
        yield node
    finally:
        if node is not None:
            node.destroy_node()
        context.try_shutdown()


@contextlib.contextmanager
def graph_node(args: object) -> Iterator[Node | daemon.DaemonGraph]:
    """The graph as a listing command sees it: the running daemon's, or (starting a
    daemon for later commands, unless `--no-daemon`) a node of its own."""
    use_daemon = not getattr(args, 'no_daemon', False)
    if use_daemon and daemon.is_running():
        yield daemon.DaemonGraph()
        return
    if use_daemon:
        daemon.spawn()
    with cli_node() as node:
        yield node
        if use_daemon:  # the next command asks the daemon: let it know what this one saw
            daemon.wait_until_seen(node_names(node, include_hidden=False))


def graph_fingerprint(node: Node) -> tuple:
    """Everything discovery can still be filling in, as one comparable value."""
    names = sorted(node.get_node_names_and_namespaces())
    endpoints = []
    for name, namespace in names:
        with contextlib.suppress(Exception):  # the node may vanish meanwhile
            endpoints.append((
                name, namespace,
                sorted(map(_freeze, node.get_publisher_names_and_types_by_node(name, namespace))),
                sorted(map(_freeze, node.get_subscriber_names_and_types_by_node(name, namespace))),
                sorted(map(_freeze, node.get_service_names_and_types_by_node(name, namespace))),
            ))
    return tuple(names), tuple(endpoints)


def _freeze(item: tuple[str, list[str]]) -> tuple[str, tuple[str, ...]]:
    return item[0], tuple(item[1])


def wait_for_graph(node: Node, until: Callable[[], bool] | None = None,
                   min_wait: float = MIN_WAIT, quiet: float = QUIET_TIME,
                   max_wait: float = MAX_WAIT) -> None:
    """Poll the graph until it stops changing, instead of a fixed long sleep.

    Returns once at least `min_wait` has passed, `until()` (if given) holds and
    the graph has been unchanged for `quiet` seconds; or after `max_wait`.
    """
    if isinstance(node, daemon.DaemonGraph):
        return  # the daemon answers with what it has seen: nothing to wait for
    min_wait = min(min_wait, max_wait)
    start = time.monotonic()
    last = None
    last_change = start
    while True:
        now = time.monotonic()
        current = graph_fingerprint(node)
        if current != last:
            last, last_change = current, now
        settled = now - start >= min_wait and now - last_change >= quiet
        if settled and (until is None or until()):
            return
        if now - start >= max_wait:
            return
        time.sleep(POLL)


def node_names(node: Node, include_hidden: bool = False) -> list[str]:
    """Full names of the nodes in the graph, sorted, hidden ones left out by default."""
    names = {full_name(n, ns) for n, ns in node.get_node_names_and_namespaces()}
    return sorted(n for n in names if include_hidden or not is_hidden(n))


def wait_until(node: Node, condition: Callable[[], bool], max_wait: float = MAX_WAIT) -> None:
    """Wait for one thing (a node, a publisher) to be discovered, then settle briefly.

    Once a participant shows up, the rest of what it offers follows within a
    fraction of a second: no need to wait for the whole graph.
    """
    wait_for_graph(node, until=condition, min_wait=QUIET_TIME, max_wait=max_wait)


def wait_for_node(node: Node, target: str, include_hidden: bool = False,
                  max_wait: float = MAX_WAIT) -> bool:
    """Wait until the named node is discovered (or time runs out); True if it was."""
    wait_until(node, lambda: target in node_names(node, include_hidden=True), max_wait)
    return target in node_names(node, include_hidden=include_hidden)
