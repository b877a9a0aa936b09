"""Talk to a running turtlesim from the test process: its messages, services and topics.

The test process did not source the workspace, so the turtlesim interfaces
built into it are loaded by hand: their libraries first (the dynamic loader
then resolves the Python extensions against them), then their Python package.
"""
from __future__ import annotations

import ctypes
import os
import sys
from pathlib import Path

import rclpy
from geometry_msgs.msg import Twist
from labkit import observer
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor

from .._polling import wait_for

LIMIT = 30.0  # seconds; a hang guard, not a speed requirement


def load_interfaces(install: Path, package: str) -> None:
    """Make ``import <package>`` of an interface package built into ``install`` work
    in this process (turtlesim, capstone_interfaces)."""
    prefix = install / package
    lib = prefix / 'lib'
    # rosidl finds the typesupport libraries on LD_LIBRARY_PATH when a type is used.
    os.environ['LD_LIBRARY_PATH'] = os.pathsep.join(
        filter(None, [str(lib), os.environ.get('LD_LIBRARY_PATH')]))
    pending = sorted(lib.glob('lib*.so'))
    for _ in range(len(pending)):  # in dependency order, whatever it is
        for library in list(pending):
            try:
                ctypes.CDLL(str(library), mode=ctypes.RTLD_GLOBAL)
                pending.remove(library)
            except OSError:
                continue
    if pending:
        raise ImportError(f'cannot load {[p.name for p in pending]} from {lib}')
    site = next(prefix.glob('lib/python3*/site-packages'))
    if str(site) not in sys.path:
        sys.path.insert(0, str(site))


def load_turtlesim_interfaces(install: Path) -> None:
    """Make ``import turtlesim`` / ``turtlesim_headless`` work in this process."""
    load_interfaces(install, 'turtlesim')


class SimClient:
    """An rclpy node in the test's domain that calls turtlesim and watches it."""

    def __init__(self) -> None:
        self.context = Context()
        rclpy.init(context=self.context)
        self.node = rclpy.create_node('turtlesim_test_client', context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.latest: dict[str, object] = {}
        self._publishers: dict[str, object] = {}

    def close(self) -> None:
        self.executor.shutdown()
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)

    def spin_until(self, condition, what: str, limit: float = LIMIT):
        """Spin until ``condition()`` is truthy; return it (fail naming ``what``)."""
        return wait_for(condition, limit, what,
                        pause=lambda: self.executor.spin_once(timeout_sec=0.05))

    def call(self, srv_type, service: str, /, **fields):
        """Call ``service`` with a request of ``fields`` and return its response.

        Through labkit's observer, the tests' one service-call helper (issue 13);
        this client's own executor only delivers the topics it watches.
        """
        response = observer.observer().call(srv_type, service, srv_type.Request(**fields), LIMIT)
        assert response is not None, f'no answer from {service} (is its node running?)'
        return response

    def watch(self, msg_type, topic: str) -> None:
        """Keep the latest message of ``topic`` in ``self.latest[topic]``."""
        self.node.create_subscription(msg_type, topic,
                                      lambda msg: self.latest.__setitem__(topic, msg), 10)

    def wait_for(self, topic: str, predicate, what: str):
        """The first latest message of ``topic`` satisfying ``predicate``."""
        def match():
            msg = self.latest.get(topic)
            return msg if msg is not None and predicate(msg) else None
        return self.spin_until(match, f'{what} on {topic}')

    def drive(self, turtle: str, linear: float = 0.0, angular: float = 0.0,
              lateral: float = 0.0) -> None:
        """Publish one velocity command once turtlesim listens on ``<turtle>/cmd_vel``."""
        topic = f'/{turtle}/cmd_vel'
        if topic not in self._publishers:
            self._publishers[topic] = self.node.create_publisher(Twist, topic, 10)
        publisher = self._publishers[topic]
        self.spin_until(lambda: publisher.get_subscription_count() > 0, f'a subscriber of {topic}')
        command = Twist()
        command.linear.x, command.linear.y, command.angular.z = linear, lateral, angular
        publisher.publish(command)

    def topics(self) -> dict[str, list[str]]:
        return dict(self.node.get_topic_names_and_types())

    def services(self) -> dict[str, list[str]]:
        return dict(self.node.get_service_names_and_types())
