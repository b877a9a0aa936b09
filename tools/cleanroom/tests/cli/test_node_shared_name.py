"""`ros2 node list` with two nodes of one name: Jazzy lists each node (two lines,
counted twice) and warns about the shared name on standard error."""
from __future__ import annotations

import pytest
from _polling import wait_for

SHARED_NAME = ('WARNING: Be aware that there are nodes in the graph that share an exact name, '
               'which can have unintended side effects.\n')


@pytest.fixture(scope='module', autouse=True)
def two_talkers_and_a_listener(start_node, ros2):
    start_node('talker')
    start_node('talker')
    start_node('listener')
    # until the daemon has seen the second talker too
    wait_for(lambda: ros2('node', 'list', '--count-nodes').stdout == '3\n', 15.0,
             'the daemon to list both talkers')


def test_each_node_is_a_line_and_the_shared_name_is_warned_about(ros2):
    result = ros2('node', 'list')
    assert (result.returncode, result.stdout, result.stderr) == (
        0, '/listener\n/sensor_publisher\n/sensor_publisher\n', SHARED_NAME)


def test_the_count_counts_both_and_does_not_warn(ros2):
    result = ros2('node', 'list', '--count-nodes')
    assert (result.stdout, result.stderr) == ('3\n', '')

