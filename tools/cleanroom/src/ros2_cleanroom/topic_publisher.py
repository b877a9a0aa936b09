"""`ros2 topic pub`: its options and its loop (wait for subscribers, publish at a rate)."""
from __future__ import annotations

import argparse
import contextlib
import os
import signal
import sys
import time
from collections.abc import Iterator
from typing import Any

import rclpy
import yaml
from rclpy.context import Context
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    LivelinessPolicy,
    QoSPresetProfiles,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_parameter_events,
    qos_profile_services_default,
)

from ros2_cleanroom.discovery_options import add_discovery_options
from ros2_cleanroom.interfaces import import_interface
from ros2_cleanroom.message_fields import set_message_fields

PROFILES = ['unknown', 'default', 'system_default', 'sensor_data', 'services_default',
            'parameters', 'parameter_events', 'action_status_default', 'best_available']
# Seconds between the "Waiting for ..." lines.
WAIT_REPORT = 1.0


def add_arguments(pub: argparse.ArgumentParser) -> None:
    pub.add_argument('topic_name', help="Name of the ROS topic to publish to (e.g. '/chatter')")
    pub.add_argument('message_type', help="Type of the ROS message (e.g. 'std_msgs/String')")
    source = pub.add_mutually_exclusive_group()
    source.add_argument('values', nargs='?', default='{}',
                        help="Values to fill the message with in YAML format (e.g. 'data: Hello "
                             "World'), otherwise the message will be published with default "
                             'values')
    source.add_argument('--stdin', action='store_true', help='Read values from standard input')
    pub.add_argument('-r', '--rate', metavar='N', type=float, default=1.0,
                     help='Publishing rate in Hz (default: 1)')
    pub.add_argument('-p', '--print', metavar='N', type=int, default=1, dest='print_nth',
                     help='Only print every N-th published message (default: 1)')
    count = pub.add_mutually_exclusive_group()
    count.add_argument('-1', '--once', action='store_true', help='Publish one message and exit')
    count.add_argument('-t', '--times', type=int, default=0,
                       help='Publish this number of times and then exit')
    pub.add_argument('-w', '--wait-matching-subscriptions', type=int, default=None,
                     help='Wait until finding the specified number of matching subscriptions. '
                          'Defaults to 1 when using "-1"/"--once"/"--times", otherwise defaults '
                          'to 0.')
    pub.add_argument('--max-wait-time-secs', type=float, default=None,
                     help='This sets the maximum wait time in seconds if '
                          '--wait-until-matching-subscriptions is set. By default, this flag is '
                          'not set meaning the subscriber will wait endlessly.')
    pub.add_argument('--keep-alive', metavar='N', type=float, default=0.1,
                     help='Keep publishing node alive for N seconds after the last msg '
                          '(default: 0.1)')
    pub.add_argument('-n', '--node-name', help='Name of the created publishing node')
    pub.add_argument('--qos-profile', choices=PROFILES, default='default',
                     help='Quality of service preset profile to publish with (default: default)')
    pub.add_argument('--qos-depth', metavar='N', type=int, default=None,
                     help='Queue size setting to publish with (overrides depth value of '
                          '--qos-profile option)')
    pub.add_argument('--qos-history', choices=['system_default', 'keep_last', 'keep_all',
                                               'unknown'], default=None,
                     help='History of samples setting to publish with (overrides history value '
                          'of --qos-profile option, default: keep_last)')
    pub.add_argument('--qos-reliability', choices=['system_default', 'reliable', 'best_effort',
                                                   'unknown', 'best_available'], default=None,
                     help='Quality of service reliability setting to publish with (overrides '
                          'reliability value of --qos-profile option, default: Compatible '
                          'profile with running endpoints )')
    pub.add_argument('--qos-durability', choices=['system_default', 'transient_local',
                                                  'volatile', 'unknown', 'best_available'],
                     default=None,
                     help='Quality of service durability setting to publish with (overrides '
                          'durability value of --qos-profile option, default: Compatible '
                          'profile with running endpoints )')
    pub.add_argument('--qos-liveliness', choices=['system_default', 'automatic',
                                                  'manual_by_topic', 'unknown', 'best_available'],
                     default=None,
                     help='Quality of service liveliness setting to publish with (overrides '
                          'liveliness value of --qos-profile option')
    pub.add_argument('--qos-liveliness-lease-duration-seconds', type=float, default=None,
                     help='Quality of service liveliness lease duration setting to publish '
                          'with (overrides liveliness lease duration value of --qos-profile '
                          'option')
    add_discovery_options(pub, no_daemon=False)


def publisher_qos(args: argparse.Namespace) -> QoSProfile:
    """The preset of `--qos-profile` with the `--qos-*` overrides applied."""
    if args.qos_profile == 'services_default':
        base = qos_profile_services_default
    elif args.qos_profile == 'parameter_events':
        base = qos_profile_parameter_events
    else:
        base = QoSPresetProfiles.get_from_short_key(args.qos_profile)
    profile = QoSProfile(history=base.history, depth=base.depth, reliability=base.reliability,
                         durability=base.durability, liveliness=base.liveliness,
                         liveliness_lease_duration=base.liveliness_lease_duration)
    if args.qos_history:
        profile.history = HistoryPolicy.get_from_short_key(args.qos_history)
    if args.qos_depth is not None:
        profile.depth = args.qos_depth
    if args.qos_reliability:
        profile.reliability = ReliabilityPolicy.get_from_short_key(args.qos_reliability)
    if args.qos_durability:
        profile.durability = DurabilityPolicy.get_from_short_key(args.qos_durability)
    if args.qos_liveliness:
        profile.liveliness = LivelinessPolicy.get_from_short_key(args.qos_liveliness)
    if args.qos_liveliness_lease_duration_seconds is not None:
        profile.liveliness_lease_duration = Duration(
            seconds=args.qos_liveliness_lease_duration_seconds)
    return profile


@contextlib.contextmanager
def publishing_node(name: str | None) -> Iterator[Node]:
    """The publishing node: `-n NAME`, else a hidden `_ros2cli_<pid>`."""
    context = Context()
    rclpy.init(args=[], context=context)
    node = None
    try:
        node = rclpy.create_node(name or f'_ros2cli_{os.getpid()}', context=context)
        yield node
    finally:
        if node is not None:
            node.destroy_node()
        context.try_shutdown()


def fail(message: str) -> int:
    print(message, file=sys.stderr)
    return 1


def publish(args: argparse.Namespace) -> int:
    """Ctrl-C (SIGINT, even one ignored by the shell that started it) ends it with exit 2."""
    signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        return _publish(args)
    except KeyboardInterrupt:
        return 2


def _publish(args: argparse.Namespace) -> int:
    try:
        msg_type = import_interface(args.message_type)
    except ValueError:
        return fail('The passed message type is invalid')
    # all of standard input is one document; malformed YAML ends in its exception
    text = sys.stdin.buffer.read() if args.stdin else args.values
    values = yaml.safe_load(text)
    if not isinstance(values, dict):
        return fail('The passed value needs to be a dictionary in YAML format')
    times = 1 if args.once else args.times
    wanted = args.wait_matching_subscriptions
    if wanted is None:
        wanted = 1 if times else 0
    with publishing_node(args.node_name) as node:
        def stamped() -> Any:
            return node.get_clock().now().to_msg()

        try:
            set_message_fields(msg_type(), values, stamped)
        except Exception as error:  # noqa: BLE001 - ros2cli reports any failure this way
            return fail(f'Failed to populate field: {error}')
        publisher = node.create_publisher(msg_type, args.topic_name, publisher_qos(args))
        if not _wait_for_subscriptions(node, publisher, wanted, args.max_wait_time_secs):
            return fail('Timed out waiting for subscribers: Expected '
                        f'{wanted} subcribers but only got '
                        f'{publisher.get_subscription_count()} subscribers')
        print('publisher: beginning loop', flush=True)
        _loop(node, publisher, msg_type, values, stamped, args, times)
    return 0


def _wait_for_subscriptions(node: Node, publisher: Any, wanted: int,
                            max_wait: float | None) -> bool:
    """Wait until `wanted` subscriptions match, saying so every WAIT_REPORT seconds."""
    if wanted <= 0:
        return True
    deadline = None if max_wait is None else time.monotonic() + max_wait
    while publisher.get_subscription_count() < wanted:
        if deadline is not None and time.monotonic() >= deadline:
            return False
        print(f'Waiting for at least {wanted} matching subscription(s)...', flush=True)
        pause = WAIT_REPORT if deadline is None else min(WAIT_REPORT,
                                                         deadline - time.monotonic())
        time.sleep(max(pause, 0.0))
    return True


def _loop(node: Node, publisher: Any, msg_type: type, values: dict, stamped: Any,
          args: argparse.Namespace, times: int) -> None:
    """Publish every 1/rate seconds (`times` messages, or until interrupted)."""
    period = 1.0 / args.rate
    count = 0
    next_time = time.monotonic()
    while node.context.ok():
        msg = msg_type()
        set_message_fields(msg, values, stamped)
        publisher.publish(msg)
        count += 1
        if args.print_nth and count % args.print_nth == 0:
            print(f'publishing #{count}: {msg!r}\n', flush=True)
        if times and count >= times:
            break
        next_time += period
        time.sleep(max(next_time - time.monotonic(), 0.0))
    time.sleep(args.keep_alive)
