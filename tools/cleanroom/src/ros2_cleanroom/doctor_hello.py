"""`ros2 doctor hello`: check that ROS messages and UDP multicast reach the other hosts.

Every emit period the command publishes `hello, it's me <hostname>` on a topic
(std_msgs/String, reliable and transient-local) and sends the same text to
multicast group 225.0.0.1, port 49150; it counts, per sending host, what it
hears on both (its subscription is best-effort).  Every print period it prints
a summary table of the counts of that period and starts again from zero.

Behaviour observed on the Jazzy reference and kept here:

* the sending host is the last word of what arrives (`data.split()[-1]`), and
  its own host's messages are not counted, so two instances on one host show
  empty tables; an empty message kills the thread that received it (a
  traceback on stderr);
* `-t` without a value leaves the topic None: rclpy's error alone, exit 1
  (ros2cli prints a RuntimeError's text); an invalid name is a traceback;
* a `--ttl` of 128 or more fails packing it into a signed byte (traceback);
* emitting and printing are timers of the node, run by the spin thread: a
  message that kills that thread (an empty one) stops both, and the command
  then waits for Ctrl-C;
* `--once` emits once, waits one emit period and prints one summary (exit 0);
* Ctrl-C ends it with exit code 0 and nothing more printed.  (Jazzy's spin
  thread sometimes races the shutdown and prints an RCLError traceback, or
  hangs; that race is not reproduced.)
"""
from __future__ import annotations

import argparse
import contextlib
import os
import socket
import struct
import sys
import threading
import time
from collections.abc import Callable

import rclpy
from rclpy.context import Context
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from std_msgs.msg import String

HELP = 'Check network connectivity between multiple hosts'
DEFAULT_TOPIC = '/canyouhearme'
GROUP = '225.0.0.1'
PORT = 49150
SUMMARY_RULE = '-' * 60
TABLE_INDENT = ' ' * 16
#: Jazzy's message for a period or TTL that is not positive, its placeholder unfilled.
NOT_POSITIVE = 'value must be a positive {type_.__name__}'


def positive(type_: type) -> Callable[[str], float | int]:
    """argparse type: a positive number of `type_` (anything else gets Jazzy's message)."""
    def convert(text: str) -> float | int:
        try:
            value = type_(text)
        except ValueError:
            value = 0
        if not value > 0:
            raise argparse.ArgumentTypeError(NOT_POSITIVE)
        return value
    return convert


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-t', '--topic', nargs='?', default=DEFAULT_TOPIC,
                        help=f"Name of ROS topic to publish to (default: '{DEFAULT_TOPIC}')")
    parser.add_argument('-ep', '--emit-period', metavar='N', type=positive(float), default=0.1,
                        help='Time period to publish/send one message (default: 0.1s)')
    parser.add_argument('-pp', '--print-period', metavar='N', type=positive(float), default=1.0,
                        help='Time period to print summary table (default: 1.0s)')
    parser.add_argument('--ttl', type=positive(int), default=None,
                        help='TTL for multicast send (default: None)')
    parser.add_argument('-1', '--once', action='store_true',
                        help='Publish and multicast send for one emit period then exit; used in '
                             'test case.')


def node_name(hostname: str) -> str:
    """`ros2doctor_<host>_<pid>_node`, the host's `-` and `.` made `_` (seen on Jazzy)."""
    host = hostname.replace('-', '_').replace('.', '_')
    return f'ros2doctor_{host}_{os.getpid()}_node'


class Counts:
    """Messages heard per sending host in this print period, in the order first heard."""

    def __init__(self, own_host: str) -> None:
        self.own_host = own_host
        self._lock = threading.Lock()
        self._hosts: dict[str, int] = {}

    def heard(self, text: str) -> None:
        host = text.split()[-1]  # IndexError on an empty message, as in Jazzy
        if host != self.own_host:
            with self._lock:
                self._hosts[host] = self._hosts.get(host, 0) + 1

    def take(self) -> dict[str, int]:
        """The period's counts, starting a new period."""
        with self._lock:
            hosts, self._hosts = self._hosts, {}
        return hosts


def table(hosts: dict[str, int], print_period: float) -> list[str]:
    rows = [('Hostname', f'Msg Count /{print_period}s'), *hosts.items()]
    return [f'{TABLE_INDENT}{host:<20} {count:<10}' for host, count in rows]


def summary(topic: str, published: int, subscribed: dict[str, int], sent: int,
            received: dict[str, int], print_period: float) -> str:
    """One summary block, as Jazzy prints it every print period."""
    return '\n'.join([
        'MULTIMACHINE COMMUNICATION SUMMARY',
        f'Topic: {topic}, Published Msg Count: {published}',
        'Subscribed from:',
        *table(subscribed, print_period),
        f'Multicast Group/Port: {GROUP}/{PORT}, Sent Msg Count: {sent}',
        'Received from:',
        *table(received, print_period),
        SUMMARY_RULE,
    ])


def _multicast_sender(ttl: int | None) -> socket.socket:
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    if ttl is not None:  # a signed byte: struct.error from 128 on, as in Jazzy
        sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, struct.pack('b', ttl))
    return sock


def _multicast_receiver() -> socket.socket:
    """Bound to the group's port; other receivers (another hello, `multicast receive`) share it."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(('', PORT))
    membership = struct.pack('4sl', socket.inet_aton(GROUP), socket.INADDR_ANY)
    sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
    return sock


class Hello:
    """The node, the two sockets, the counters and the threads of one `ros2 doctor hello`."""

    def __init__(self, args: argparse.Namespace, context: Context) -> None:
        self.args = args
        self.hostname = socket.gethostname()
        self.message = f"hello, it's me {self.hostname}"
        self.published = self.sent = 0
        self.subscribed = Counts(self.hostname)
        self.received = Counts(self.hostname)
        self.node = rclpy.create_node(node_name(self.hostname), context=context,
                                      start_parameter_services=False)
        qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.publisher = self.node.create_publisher(String, args.topic, qos)
        self.node.create_subscription(String, args.topic,
                                      lambda msg: self.subscribed.heard(msg.data),
                                      qos_profile_sensor_data)
        self.sender = _multicast_sender(args.ttl)
        self.receiver = _multicast_receiver()
        self.executor = SingleThreadedExecutor(context=context)
        self.executor.add_node(self.node)

    def emit(self) -> None:
        self.publisher.publish(String(data=self.message))
        self.published += 1
        self.sender.sendto(self.message.encode('utf-8'), (GROUP, PORT))
        self.sent += 1

    def recv(self) -> None:
        """Thread: count the datagrams of the group, until the command ends."""
        while True:
            data, _ = self.receiver.recvfrom(4096)
            self.received.heard(data.decode('utf-8'))

    def spin(self) -> None:
        """Thread: deliver the subscription's messages (and the emit timer) until shutdown."""
        with contextlib.suppress(ExternalShutdownException):
            self.executor.spin()

    def start(self) -> threading.Thread:
        # Named after their functions, as Jazzy's threads are: `Thread-1 (recv)`
        # and `Thread-2 (spin)` head the traceback when one of them dies.
        threading.Thread(target=self.recv, daemon=True).start()
        spinner = threading.Thread(target=self.spin, daemon=True)
        spinner.start()
        return spinner

    def print_summary(self) -> None:
        published, self.published = self.published, 0
        sent, self.sent = self.sent, 0
        print(summary(self.args.topic, published, self.subscribed.take(), sent,
                      self.received.take(), self.args.print_period), flush=True)

    def close(self) -> None:
        self.sender.close()
        self.node.destroy_node()


def hello(args: argparse.Namespace) -> int:
    context = Context()
    rclpy.init(args=[], context=context)
    spinner = None
    checker = None
    try:
        checker = Hello(args, context)
        if args.once:
            spinner = checker.start()
            checker.emit()
            time.sleep(args.emit_period)
            checker.print_summary()
            return 0
        checker.node.create_timer(args.emit_period, checker.emit)
        checker.node.create_timer(args.print_period, checker.print_summary)
        spinner = checker.start()
        while True:  # until Ctrl-C, even once the spin thread has died
            time.sleep(1.0)
    except RuntimeError as exc:  # rclpy's errors: ros2cli prints their text alone
        print(exc, file=sys.stderr)
        return 1
    finally:
        context.try_shutdown()
        if spinner is not None:
            spinner.join(timeout=2.0)
        if checker is not None:
            checker.close()
