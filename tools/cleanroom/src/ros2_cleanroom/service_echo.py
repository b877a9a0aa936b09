"""`ros2 service echo`: print a service's introspection events as Jazzy does.

A client or server with introspection on publishes a `<Srv>_Event` message
on `<service>/_service_event` for each request and response; echo prints
them as `ros2 topic echo` prints messages.  With introspection off nobody
publishes there: Jazzy says so once and keeps waiting.  Ctrl-C ends it with
exit code 2 (SIGINT's number), as ros2cli's own interrupt handling returns.
"""
from __future__ import annotations

import argparse
import signal
import sys
from typing import Any

from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

from ros2_cleanroom import cli_node
from ros2_cleanroom.interfaces import import_interface
from ros2_cleanroom.service_event_format import format_event
from ros2_cleanroom.verb_args import fail

EVENT_SUFFIX = '/_service_event'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Jazzy's `ros2 service echo` options, in its order and words."""
    parser.add_argument('service_name',
                        help="Name of the ROS service to echo (e.g. '/add_two_ints')")
    parser.add_argument('service_type', nargs='?',
                        help="Type of the ROS service (e.g. 'example_interfaces/srv/AddTwoInts')")
    parser.add_argument('--csv', action='store_true',
                        help='Output all recursive fields separated by commas (e.g. for '
                             'plotting).')
    parser.add_argument('--full-length', '-f', action='store_true',
                        help="Output all elements for arrays, bytes, and string with a length > "
                             "'--truncate-length', by default they are truncated after "
                             "'--truncate-length' elements with '...''")
    parser.add_argument('--truncate-length', '-l', type=int, default=128,
                        help='The length to truncate arrays, bytes, and string to (default: 128)')
    parser.add_argument('--no-arr', action='store_true',
                        help="Don't print array fields of messages")
    parser.add_argument('--no-str', action='store_true',
                        help="Don't print string fields of messages")
    parser.add_argument('--flow-style', action='store_true',
                        help='Print collections in the block style (not available with csv '
                             'format)')


def _service_types(args: argparse.Namespace) -> list[str]:
    """The service's types in the graph (the name taken as given, as Jazzy does)."""
    def types_now(node: Any) -> list[str]:
        return dict(node.get_service_names_and_types()).get(args.service_name, [])

    with cli_node.graph_node(args) as node:
        if isinstance(node, Node):
            cli_node.wait_until(node, lambda: bool(types_now(node)))
        return list(types_now(node))


def _event_type(args: argparse.Namespace) -> type:
    """The `<Srv>_Event` message class; RuntimeError with Jazzy's message if unknown."""
    name = args.service_type
    if name is None:
        types = _service_types(args)
        if not types:
            raise RuntimeError(f"Cannot find type for '{args.service_name}'")
        name = types[0]
    try:
        return import_interface(name, kind='srv').Event
    except (ValueError, AttributeError):
        raise RuntimeError(f"The service type '{name}' is invalid") from None


def echo_service(args: argparse.Namespace) -> int:
    try:
        event_type = _event_type(args)
    except RuntimeError as error:
        return fail(str(error))
    try:
        _echo(args.service_name + EVENT_SUFFIX, event_type, args)
    except KeyboardInterrupt:
        return int(signal.SIGINT)
    return 0


def _echo(topic: str, event_type: type, args: argparse.Namespace) -> None:
    """Print the events on `topic` until Ctrl-C."""
    with cli_node.cli_node() as node:
        def on_event(msg: Any) -> None:
            sys.stdout.write(format_event(msg, args))
            sys.stdout.flush()

        resolved = node.create_subscription(event_type, topic, on_event, 10).topic_name
        # Jazzy asks its daemon, which has long seen the publishers: wait for discovery
        cli_node.wait_until(node, lambda: bool(node.get_publishers_info_by_topic(resolved)))
        if not node.get_publishers_info_by_topic(resolved):
            print(f"No publishers on topic '{resolved}'; is service introspection on the client "
                  'or server enabled?', flush=True)
        executor = SingleThreadedExecutor(context=node.context)
        executor.add_node(node)
        try:
            while node.context.ok():
                executor.spin_once(timeout_sec=0.1)
        finally:
            executor.shutdown(timeout_sec=0)
