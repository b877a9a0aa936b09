"""Subscription QoS for `ros2 topic echo|hz` that matches whoever publishes.

A subscriber that asks for more than a publisher offers (reliable vs best
effort, transient local vs volatile) receives nothing, so, like ros2cli, the
verbs ask for the strongest policy that every current publisher offers.
Explicit `--qos-*` options win.
"""
from __future__ import annotations

import argparse

from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy


def add_qos_arguments(parser: argparse.ArgumentParser) -> None:
    """The `--qos-*` options of ros2cli's echo and hz."""
    parser.add_argument('--qos-depth', type=int, default=None,
                        help='Queue size setting to subscribe with')
    parser.add_argument('--qos-reliability', choices=['system_default', 'reliable', 'best_effort'],
                        default=None, help='Quality of service reliability setting')
    parser.add_argument('--qos-durability',
                        choices=['system_default', 'transient_local', 'volatile'],
                        default=None, help='Quality of service durability setting')


def subscription_qos(node: Node, topic: str, args: argparse.Namespace) -> QoSProfile:
    """A QoS profile compatible with every publisher of `topic` seen so far."""
    offered = [info.qos_profile for info in node.get_publishers_info_by_topic(topic)]
    reliability = ReliabilityPolicy.RELIABLE
    if offered and any(q.reliability == ReliabilityPolicy.BEST_EFFORT for q in offered):
        reliability = ReliabilityPolicy.BEST_EFFORT
    durability = DurabilityPolicy.VOLATILE
    if offered and all(q.durability == DurabilityPolicy.TRANSIENT_LOCAL for q in offered):
        durability = DurabilityPolicy.TRANSIENT_LOCAL
    if args.qos_reliability:
        reliability = ReliabilityPolicy[args.qos_reliability.upper()]
    if args.qos_durability:
        durability = DurabilityPolicy[args.qos_durability.upper()]
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=args.qos_depth or 10,
                      reliability=reliability, durability=durability)
