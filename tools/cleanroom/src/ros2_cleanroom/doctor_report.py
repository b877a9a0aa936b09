"""The sections of `ros2 doctor --report` and their `key : value` layout.

Jazzy prints the sections in alphabetical order, each as a blank line, the
title indented by three spaces, then its rows with the keys padded to the
longest key of the section plus four.  The PACKAGE VERSIONS and ROS 2
INFORMATION sections need the rosdistro index from the internet; the
recorded Jazzy run (no network) printed neither, and nor does this one.
"""
from __future__ import annotations

import platform

from rclpy.utilities import get_rmw_implementation_identifier

from ros2_cleanroom import network_info
from ros2_cleanroom.doctor_graph import QosPair, TopicEndpoints

Rows = list[tuple[str, str]]


def format_section(title: str, rows: Rows) -> str:
    """`\\n   TITLE\\nkey    : value...` for one section."""
    width = max((len(key) for key, _ in rows), default=0) + 4
    lines = ['', f'   {title}'] + [f'{key:<{width}}: {value}' for key, value in rows]
    return '\n'.join(lines)


def network_rows() -> Rows:
    return [(key, value) for device in network_info.interfaces() for key, value in device.items()]


def platform_rows() -> Rows:
    return [('system', platform.system()), ('platform info', platform.platform()),
            ('release', platform.release()), ('processor', platform.processor())]


def qos_rows(pairs: list[QosPair]) -> Rows:
    if not pairs:
        return [('topic [type]', 'none'), ('publisher node', 'none'),
                ('subscriber node', 'none'), ('compatibility status', 'none')]
    rows: Rows = []
    for pair in pairs:
        rows += [('topic [type]', f"{pair.topic} [{', '.join(pair.types)}]"),
                 ('publisher node', pair.publisher_node),
                 ('subscriber node', pair.subscriber_node),
                 ('compatibility status', pair.status)]
    return rows


def rmw_rows() -> Rows:
    return [('middleware name', get_rmw_implementation_identifier())]


def topic_rows(topics: list[TopicEndpoints]) -> Rows:
    if not topics:
        return [('topic', 'none'), ('publisher count', '0'), ('subscriber count', '0')]
    rows: Rows = []
    for topic in topics:
        rows += [('topic', topic.name), ('publisher count', str(len(topic.publishers))),
                 ('subscriber count', str(len(topic.subscribers)))]
    return rows


def report(topics: list[TopicEndpoints], pairs: list[QosPair],
           only: set[str] | None = None) -> str:
    """The whole report; `only` limits it to the sections of these check categories."""
    sections = [
        ('network', 'NETWORK CONFIGURATION', network_rows),
        ('platform', 'PLATFORM INFORMATION', platform_rows),
        ('middleware', 'QOS COMPATIBILITY LIST', lambda: qos_rows(pairs)),
        ('middleware', 'RMW MIDDLEWARE', rmw_rows),
        ('topic', 'TOPIC LIST', lambda: topic_rows(topics)),
    ]
    return '\n'.join(format_section(title, rows())
                     for category, title, rows in sections if only is None or category in only)
