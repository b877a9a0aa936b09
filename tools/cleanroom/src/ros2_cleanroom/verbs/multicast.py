"""`ros2 multicast send|receive`: check that UDP multicast works between two hosts.

DDS discovers peers over multicast, so this is the first thing to try when
nodes on two machines do not see each other.  One datagram, as Jazzy sends it:
group 225.0.0.1, port 49150, text `Hello World!`.  Socket errors (a bad group,
a port out of range) are not caught, as Jazzy does not catch them.
"""
from __future__ import annotations

import argparse
import socket
import struct

from ros2_cleanroom.verb_args import add_verb, command_parser, run

DEFAULT_GROUP = '225.0.0.1'
DEFAULT_PORT = 49150
MESSAGE = b'Hello World!'


def positive_int(text: str) -> int:
    """argparse type: Jazzy's words for a port or TTL that is not a positive integer."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise argparse.ArgumentTypeError('value must be a positive integer')
    return value


def _add_group_and_port(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--group', default=DEFAULT_GROUP, help='The multicast group address')
    parser.add_argument('--port', type=positive_int, default=DEFAULT_PORT,
                        help='The multicast port')


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('multicast', 'Various multicast related sub-commands')
    receive = add_verb(verbs, 'receive', 'Receive a single UDP multicast packet', receive_one)
    _add_group_and_port(receive)
    send = add_verb(verbs, 'send', 'Send a single UDP multicast packet', send_one)
    _add_group_and_port(send)
    send.add_argument('--ttl', type=positive_int, default=None, help='The multicast TTL')
    return parser


def send_one(args: argparse.Namespace) -> int:
    print('Sending one UDP multicast datagram...', flush=True)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP) as sock:
        if args.ttl is not None:  # a signed byte, as Jazzy packs it (128..255 fail)
            sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, struct.pack('b', args.ttl))
        sock.sendto(MESSAGE, (args.group, args.port))
    return 0


def receive_one(args: argparse.Namespace) -> int:
    """Wait (without a timeout) for one datagram; other receivers may share the port."""
    print('Waiting for UDP multicast datagram...', flush=True)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP) as sock:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(('', args.port))
        membership = struct.pack('4sl', socket.inet_aton(args.group), socket.INADDR_ANY)
        sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
        data, (host, port) = sock.recvfrom(4096)
    print(f"Received from {host}:{port}: '{data.decode('utf-8')}'")
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
