"""Namespace composition rules (conformance golden 06)."""
import pytest
from launch_ros.utilities.namespace_utils import (
    full_node_namespace,
    fully_qualified_name,
    make_namespace_absolute,
    prefix_namespace,
)


@pytest.mark.parametrize('pushed, own, expected', [
    (None, None, None),
    (None, 'ns1', '/ns1'),
    (None, '/abs', '/abs'),
    ('/robot1', None, '/robot1'),
    ('/robot1', 'sensors', '/robot1/sensors'),
    ('/robot1', '/fixed', '/fixed'),
    ('/robot1/arm', None, '/robot1/arm'),
    ('/', 'ns', '/ns'),
    (None, '', '/'),  # Node(namespace='') is the root: Jazzy passes -r __ns:=/ (observed)
    ('/fleet', '', '/fleet'),
])
def test_full_node_namespace(pushed, own, expected):
    assert full_node_namespace(pushed, own) == expected


def test_prefix_namespace_composes_pushes():
    assert prefix_namespace(prefix_namespace(None, 'robot1'), 'arm') == 'robot1/arm'
    assert prefix_namespace('/robot1', '/other') == '/other'
    assert prefix_namespace('/robot1/', 'arm') == '/robot1/arm'


def test_make_namespace_absolute():
    assert make_namespace_absolute('a/b') == '/a/b'
    assert make_namespace_absolute('/a') == '/a'


def test_fully_qualified_name():
    assert fully_qualified_name('/fleet', 'member') == '/fleet/member'
    assert fully_qualified_name('/', 'talker') == '/talker'
    assert fully_qualified_name(None, 'talker') == '/talker'
