"""`ros2 multicast send|receive` in Jazzy's words (outputs recorded from the Jazzy reference).

One datagram goes to group 225.0.0.1 with TTL 1, so it stays on this host's link.
`ros2 doctor hello` sends to the same group and port, so its tests never run
beside these (one xdist group): a hello datagram would be received here.
"""
from __future__ import annotations

import re

import pytest

pytestmark = pytest.mark.xdist_group('doctor_hello_multicast')

SEND_HELP = """\
usage: ros2 multicast send [-h] [--group GROUP] [--port PORT] [--ttl TTL]

Send a single UDP multicast packet

options:
  -h, --help     show this help message and exit
  --group GROUP  The multicast group address
  --port PORT    The multicast port
  --ttl TTL      The multicast TTL
"""

BAD_PORT = """\
usage: ros2 multicast send [-h] [--group GROUP] [--port PORT] [--ttl TTL]
ros2 multicast send: error: argument --port: value must be a positive integer
"""


def test_send_help(ros2):
    result = ros2('multicast', 'send', '-h', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout) == (0, SEND_HELP)


def test_a_port_must_be_positive(ros2):
    result = ros2('multicast', 'send', '--port', '0', env={'COLUMNS': '80'})
    assert (result.returncode, result.stderr) == (2, BAD_PORT)


def test_receive_what_send_sends(ros2, ros2_background):
    receiver = ros2_background('multicast', 'receive')
    assert receiver.stdout.readline() == 'Waiting for UDP multicast datagram...\n'
    sent = ros2('multicast', 'send')
    assert (sent.returncode, sent.stdout) == (0, 'Sending one UDP multicast datagram...\n')
    assert re.fullmatch(r"Received from [0-9.]+:\d+: 'Hello World!'\n", receiver.stdout.readline())
    assert receiver.wait(timeout=10) == 0
