"""`ros2 topic list|info|echo|hz|type|find|pub|bw|delay`: topics in the graph and the data
on them."""
from __future__ import annotations

import argparse
import signal
import sys
import time
from collections.abc import Callable
from typing import Any

import yaml
from rclhelpers.names import is_hidden
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node

from ros2_cleanroom import cli_node, topic_publisher
from ros2_cleanroom.discovery_options import add_discovery_options
from ros2_cleanroom.interfaces import (
    import_interface,
    message_to_csv,
    message_to_data,
    message_to_yaml,
)
from ros2_cleanroom.rate_window import RateWindow
from ros2_cleanroom.topic_qos import add_qos_arguments, subscription_qos
from ros2_cleanroom.topic_statistics import BandwidthWindow, DelayWindow
from ros2_cleanroom.verb_args import add_spin_time, add_verb, command_parser, fail, run


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('topic', 'Various topic related sub-commands')
    # Jazzy has it on the command too; each sub-verb's own default wins over it.
    parser.add_argument('--include-hidden-topics', action='store_true',
                        help='Consider hidden topics as well')

    listing = add_verb(verbs, 'list', 'Output a list of available topics', list_topics)
    listing.add_argument('-t', '--show-types', action='store_true',
                         help='Additionally show the topic type')
    listing.add_argument('-c', '--count-topics', action='store_true',
                         help='Only display the number of topics discovered')
    listing.add_argument('--include-hidden-topics', action='store_true',
                         help='Consider hidden topics as well')
    listing.add_argument('-v', '--verbose', action='store_true',
                         help='List full details about each topic')
    add_spin_time(listing)

    info = add_verb(verbs, 'info', 'Print information about a topic', topic_info)
    info.add_argument('topic_name', help="Name of the ROS topic to get info (e.g. '/chatter')")
    info.add_argument('-v', '--verbose', action='store_true',
                      help='Prints detailed information like the node name, node namespace, '
                           'topic type, topic type hash, GUID, and QoS Profile of the '
                           'publishers and subscribers to this topic')
    add_spin_time(info)

    echo = add_verb(verbs, 'echo', 'Output messages from a topic', echo_topic)
    echo.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    echo.add_argument('message_type', nargs='?',
                      help="Type of the ROS message (e.g. 'std_msgs/msg/String')")
    echo.add_argument('--once', action='store_true',
                      help='Print the first message received and then exit')
    echo.add_argument('--csv', action='store_true',
                      help='Output all recursive fields separated by commas (e.g. for plotting)')
    echo.add_argument('--filter', dest='filter_expr', default=None,
                      help='Python expression to filter messages that are printed. Expression '
                           'can use Python builtins as well as m (the message).')
    echo.add_argument('--timeout', type=float, default=None,
                      help='Stop echoing after this many seconds (exit code 0)')
    echo.add_argument('--field', default=None,
                      help='Echo a selected field of a message, e.g. linear.x')
    echo.add_argument('-f', '--full-length', action='store_true',
                      help='Output all elements for arrays, bytes, and string with a '
                           "length > '--truncate-length'")
    echo.add_argument('-l', '--truncate-length', type=int, default=128,
                      help='The length to truncate arrays, bytes, and string to (default: 128)')
    echo.add_argument('--no-arr', action='store_true', help="Don't print array fields of messages")
    echo.add_argument('--no-str', action='store_true',
                      help="Don't print string fields of messages")
    echo.add_argument('--flow-style', action='store_true',
                      help='Print collections in the block style (not available with csv format)')
    add_qos_arguments(echo)
    add_spin_time(echo)

    hz = add_verb(verbs, 'hz', 'Print the average publishing rate to screen', topic_hz)
    hz.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    hz.add_argument('-w', '--window', type=int, default=10000,
                    help='window size, in # of messages, for calculating rate (default: 10000)')
    hz.add_argument('--wall-time', action='store_true',
                    help='calculates rate using wall time (the only clock used here)')
    add_qos_arguments(hz)
    add_spin_time(hz)

    type_ = add_verb(verbs, 'type', "Print a topic's type", topic_type)
    type_.add_argument('topic_name', help="Name of the ROS topic to get type (e.g. '/chatter')")
    add_discovery_options(type_)

    pub = add_verb(verbs, 'pub', 'Publish a message to a topic', topic_publisher.publish)
    topic_publisher.add_arguments(pub)

    bw = add_verb(verbs, 'bw', 'Display bandwidth used by topic', topic_bw)
    bw.add_argument('topic', help='Topic name to monitor for bandwidth utilization')
    bw.add_argument('--window', '-w', type=int, default=100,
                    help='maximum window size, in # of messages, for calculating rate '
                         '(default: 100)')
    add_discovery_options(bw, no_daemon=False)

    delay = add_verb(verbs, 'delay', 'Display delay of topic from timestamp in header',
                     topic_delay)
    delay.add_argument('topic', help='Topic name to calculate the delay for')
    delay.add_argument('--window', '-w', type=int, default=10000,
                       help='window size, in # of messages, for calculating rate, string to '
                            '(default: 10000)')
    add_discovery_options(delay, no_daemon=False)

    find = add_verb(verbs, 'find', 'Output a list of available topics of a given type',
                    find_topics)
    find.add_argument('topic_type',
                      help="Name of the ROS topic type to filter for (e.g. 'std_msg/msg/String')")
    add_discovery_options(find)
    find.add_argument('-c', '--count-topics', action='store_true',
                      help='Only display the number of topics discovered')
    find.add_argument('--include-hidden-topics', action='store_true',
                      help='Consider hidden topics as well')
    return parser


def _absolute(topic: str) -> str:
    return topic if topic.startswith('/') else '/' + topic


def _max_wait(args: argparse.Namespace) -> float:
    return args.spin_time if args.spin_time is not None else cli_node.MAX_WAIT


def _topics(node: Node, include_hidden: bool) -> list[tuple[str, list[str]]]:
    return sorted((name, list(types)) for name, types in node.get_topic_names_and_types()
                  if include_hidden or not is_hidden(name))


def _others(node: Node, infos: list[Any]) -> list[Any]:
    """Endpoints of other nodes: the command's own node is not part of the system."""
    own = (node.get_name(), node.get_namespace())
    return [info for info in infos if (info.node_name, info.node_namespace) != own]


def _count(node: Node, infos: list[Any]) -> int:
    return len(_others(node, infos))


def list_topics(args: argparse.Namespace) -> int:
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args))
        topics = _topics(node, args.include_hidden_topics)
        if args.verbose:
            print_verbose_list(node, topics)
            return 0
    if args.count_topics:
        print(len(topics))
        return 0
    for name, types in topics:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)
    return 0


def print_verbose_list(node: Node, topics: list[tuple[str, list[str]]]) -> None:
    sections = (('Published topics:', node.get_publishers_info_by_topic, 'publisher'),
                ('Subscribed topics:', node.get_subscriptions_info_by_topic, 'subscriber'))
    for title, query, noun in sections:
        print(title)
        for name, types in topics:
            count = _count(node, query(name))
            if count:
                plural = '' if count == 1 else 's'
                print(f" * {name} [{', '.join(types)}] {count} {noun}{plural}")
        print()


def topic_info(args: argparse.Namespace) -> int:
    topic = _absolute(args.topic_name)
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args),
                                until=lambda: topic in dict(_topics(node, True)))
        types = dict(_topics(node, True)).get(topic)
        if types is None:
            return fail(f"Unknown topic '{topic}'")
        publishers = _others(node, node.get_publishers_info_by_topic(topic))
        subscribers = _others(node, node.get_subscriptions_info_by_topic(topic))
    if args.verbose:
        print(topic_info_verbose(types, publishers, subscribers), end='')
        return 0
    print(f"Type: {'; '.join(types)}")
    print(f'Publisher count: {len(publishers)}')
    print(f'Subscription count: {len(subscribers)}')
    return 0


def topic_info_verbose(types: list[str], publishers: list[Any], subscribers: list[Any]) -> str:
    """`topic info -v`: each endpoint with its QoS, a blank line after every block."""
    blocks = [f"Type: {'; '.join(types)}", f'Publisher count: {len(publishers)}']
    blocks += [str(info) for info in publishers]  # rclpy's TopicEndpointInfo text
    blocks.append(f'Subscription count: {len(subscribers)}')
    blocks += [str(info) for info in subscribers]
    return ''.join(block + '\n\n' for block in blocks)


def topic_type(args: argparse.Namespace) -> int:
    """The topic's types, one a line; an unknown (or hidden) topic fails silently.

    The name is taken as given: `chatter` is not `/chatter`.
    """
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args),
                                until=lambda: args.topic_name in dict(_topics(node, False)))
        types = dict(_topics(node, False)).get(args.topic_name)
    if not types:
        return 1
    for name in types:
        print(name)
    return 0


def find_topics(args: argparse.Namespace) -> int:
    """Topics that carry `topic_type` (spelled exactly as the graph spells it)."""
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args))
        topics = [name for name, types in _topics(node, args.include_hidden_topics)
                  if args.topic_type in types]
    if args.count_topics:
        print(len(topics))
        return 0
    for name in topics:
        print(name)
    return 0


def _resolve_type(node: Node, topic: str, given: str | None) -> type:
    """The message class to subscribe with, from the argument or the graph.

    Raises RuntimeError with ros2cli's message when it cannot be determined.
    """
    if given:
        try:
            return import_interface(given)
        except ValueError:
            raise RuntimeError('The passed message type is invalid') from None
    types = dict(_topics(node, True)).get(topic)
    if not types:
        raise RuntimeError('Could not determine the type for the passed topic')
    if len(types) > 1:
        raise RuntimeError(f"Cannot echo topic '{topic}', as it contains more than one type: "
                           f"[{', '.join(types)}]")
    try:
        return import_interface(types[0])
    except ValueError:
        raise RuntimeError(f"The message type '{types[0]}' is invalid") from None


def _warn_if_unpublished(node: Node, topic: str) -> bool:
    if node.get_publishers_info_by_topic(topic):
        return False
    _warn_unpublished(topic)
    return True


def _warn_unpublished(topic: str) -> None:
    print(f'WARNING: topic [{topic}] does not appear to be published yet', flush=True)


def _select_field(msg: Any, field: str | None) -> Any:
    for part in (field.split('.') if field else []):
        if not hasattr(msg, 'get_fields_and_field_types') or not hasattr(msg, part):
            raise RuntimeError(f"Invalid field '{field}': '{part}' is not a field of the message")
        msg = getattr(msg, part)
    return msg


def format_message(msg: Any, args: argparse.Namespace) -> str:
    """One echoed message as YAML without the trailing `---`, or one `--csv` line."""
    value = _select_field(msg, args.field)
    truncate = None if args.full_length else args.truncate_length
    if args.csv:
        return message_to_csv(value, truncate, args.no_arr, args.no_str) + '\n'
    if hasattr(value, 'get_fields_and_field_types'):
        return message_to_yaml(value, truncate, args.no_arr, args.no_str, args.flow_style)
    data = message_to_data(value, truncate, args.no_arr, args.no_str)
    text = yaml.safe_dump(data, default_flow_style=args.flow_style, width=float('inf'),
                          allow_unicode=True)
    return text[:-len('...\n')] if text.endswith('\n...\n') else text


def _spin(node: Node, done: Callable[[], bool]) -> None:
    """Spin until `done()`; Ctrl-C or SIGTERM end it quietly, as ros2cli does."""
    executor = SingleThreadedExecutor(context=node.context)
    executor.add_node(node)
    try:
        while node.context.ok() and not done():
            executor.spin_once(timeout_sec=0.1)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        executor.shutdown(timeout_sec=0)


def _interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt


def _stop_on_sigterm() -> None:
    """Let SIGTERM (e.g. from a notebook or `timeout`) end a stream like Ctrl-C."""
    signal.signal(signal.SIGTERM, _interrupt)


def _message_filter(expression: str | None) -> Callable[[Any], bool]:
    """`--filter 'm.data != ""'`: a predicate on the message `m`."""
    if not expression:
        return lambda msg: True
    code = compile(expression, '<filter>', 'eval')
    return lambda msg: bool(eval(code, {}, {'m': msg}))  # noqa: S307 - the user's own expression


def echo_topic(args: argparse.Namespace) -> int:
    topic = _absolute(args.topic_name)
    try:
        accept = _message_filter(args.filter_expr)
    except SyntaxError as error:
        return fail(f"argument --filter: invalid expression '{args.filter_expr}': {error.msg}")
    _stop_on_sigterm()
    with cli_node.cli_node() as node:
        cli_node.wait_until(node, lambda: bool(node.get_publishers_info_by_topic(topic)),
                            max_wait=_max_wait(args))
        # Jazzy warns only when it needs the type from the graph and the graph has none
        # (a topic with only subscriptions has their type: no warning)
        if args.message_type is None and topic not in dict(_topics(node, True)):
            _warn_unpublished(topic)
        try:
            msg_type = _resolve_type(node, topic, args.message_type)
        except RuntimeError as error:
            return fail(str(error))
        received = [0]
        errors: list[str] = []

        def on_message(msg: Any) -> None:
            if args.once and received[0]:
                return
            try:
                if not accept(msg):
                    return
                text = format_message(msg, args)
            except Exception as error:  # noqa: BLE001 - a bad field or a failing --filter
                errors.append(str(error))
                return
            received[0] += 1
            sys.stdout.write(text if args.csv else text + '---\n')
            sys.stdout.flush()

        node.create_subscription(msg_type, topic, on_message, subscription_qos(node, topic, args))
        deadline = None if args.timeout is None else time.monotonic() + args.timeout

        def timed_out() -> bool:  # --timeout bounds the whole echo, messages or not
            return deadline is not None and time.monotonic() >= deadline

        _spin(node, lambda: bool(errors) or (args.once and received[0] > 0) or timed_out())
    return fail(errors[0]) if errors else 0


def topic_hz(args: argparse.Namespace) -> int:
    topic = _absolute(args.topic_name)
    if args.window < 2:
        return fail(f'argument -w/--window: must be at least 2, got {args.window}')
    _stop_on_sigterm()
    with cli_node.cli_node() as node:
        cli_node.wait_until(node, lambda: bool(node.get_publishers_info_by_topic(topic)),
                            max_wait=_max_wait(args))
        if _warn_if_unpublished(node, topic):
            _spin(node, lambda: bool(node.get_publishers_info_by_topic(topic)))
            if not node.context.ok() or not node.get_publishers_info_by_topic(topic):
                return 0
        try:
            msg_type = _resolve_type(node, topic, None)
        except RuntimeError as error:
            return fail(str(error))
        window = RateWindow(args.window)
        node.create_subscription(msg_type, topic, lambda _: window.add(time.monotonic()),
                                 subscription_qos(node, topic, args), raw=True)
        next_report = [time.monotonic() + 1.0]

        def report_due() -> bool:
            if time.monotonic() >= next_report[0]:
                next_report[0] += 1.0
                text = window.report()
                if text:
                    print(text, flush=True)
            return False

        _spin(node, report_due)
    return 0


class _Interrupted(Exception):
    """Ctrl-C or SIGTERM during `bw` or `delay`, which then exit 2 as Jazzy's do."""


def _stream_statistics(args: argparse.Namespace, setup: Callable[[Node, type], Callable[[],
                       str | None]]) -> int:
    """Wait for a publisher (warning once), subscribe via `setup`, report every second.

    `setup(node, msg_type)` subscribes and returns the report function.
    """
    topic = _absolute(args.topic)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    _stop_on_sigterm()
    try:
        with cli_node.cli_node() as node:
            cli_node.wait_until(node, lambda: bool(node.get_publishers_info_by_topic(topic)),
                                max_wait=_max_wait(args))
            if _warn_if_unpublished(node, topic):
                _spin_or_raise(node, lambda: bool(node.get_publishers_info_by_topic(topic)))
            try:
                msg_type = _resolve_type(node, topic, None)
            except RuntimeError as error:
                return fail(str(error))
            report = setup(node, msg_type)
            next_report = [time.monotonic() + 1.0]
            failure: list[str] = []

            def report_due() -> bool:
                try:
                    text = report() if time.monotonic() >= next_report[0] else None
                except RuntimeError as error:
                    failure.append(str(error))
                    return True
                if time.monotonic() >= next_report[0]:
                    next_report[0] += 1.0
                    if text:
                        print(text, flush=True)
                return False

            _spin_or_raise(node, report_due)
            return fail(failure[0]) if failure else 0
    except (_Interrupted, KeyboardInterrupt):
        return 2


def _spin_or_raise(node: Node, done: Callable[[], bool]) -> None:
    """Spin until `done()`; an interrupt raises _Interrupted."""
    executor = SingleThreadedExecutor(context=node.context)
    executor.add_node(node)
    try:
        while not done():
            executor.spin_once(timeout_sec=0.1)
    except (KeyboardInterrupt, ExternalShutdownException):
        raise _Interrupted from None
    finally:
        executor.shutdown(timeout_sec=0)


def topic_bw(args: argparse.Namespace) -> int:
    def setup(node: Node, msg_type: type) -> Callable[[], str | None]:
        window = BandwidthWindow(args.window)
        node.create_subscription(msg_type, _absolute(args.topic),
                                 lambda raw: window.add(time.monotonic(), len(raw)),
                                 subscription_qos(node, _absolute(args.topic), _no_qos()),
                                 raw=True)
        print(f'Subscribed to [{_absolute(args.topic)}]', flush=True)
        return lambda: window.report(time.monotonic())

    return _stream_statistics(args, setup)


def topic_delay(args: argparse.Namespace) -> int:
    def setup(node: Node, msg_type: type) -> Callable[[], str | None]:
        window = DelayWindow(args.window)
        missing: list[bool] = []

        def on_message(msg: Any) -> None:
            if not hasattr(msg, 'header'):
                missing.append(True)
                return
            received = node.get_clock().now().nanoseconds
            stamp = msg.header.stamp.sec * 10**9 + msg.header.stamp.nanosec
            window.add((received - stamp) / 1e9)

        def report() -> str | None:
            if missing:
                raise RuntimeError('msg does not have header')
            return window.report()

        node.create_subscription(msg_type, _absolute(args.topic), on_message,
                                 subscription_qos(node, _absolute(args.topic), _no_qos()))
        return report

    return _stream_statistics(args, setup)


def _no_qos() -> argparse.Namespace:
    """No `--qos-*` options: bw and delay subscribe compatibly with the publishers."""
    return argparse.Namespace(qos_depth=None, qos_reliability=None, qos_durability=None)


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
