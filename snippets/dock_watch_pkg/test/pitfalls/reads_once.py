"""Lesson 6.15, pitfall: an output check whose result depends on when it runs.

    launch_test reads_once.py system:=<launch file>

test_a and test_c are the same check: the planner's first report is in the
output collected so far.  It reads that output once.  Whether the line is
there yet depends on what ran before (unittest runs a class's tests in the
order of their names), not on the system: test_b, which waits for the line,
is the robust form.
"""
import unittest

import launch
import launch_testing.actions
import launch_testing.asserts
import pytest
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration

TIMEOUT = 30.0  # seconds; ends a wait that would hang, never a speed limit


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        DeclareLaunchArgument('system', description='The launch file under test'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(LaunchConfiguration('system'))),
        launch_testing.actions.ReadyToTest(),
    ])


# [START reads_once]
class TestDockWatch(unittest.TestCase):

    def test_a_reads_once(self, proc_output):  # runs first
        launch_testing.asserts.assertInStderr(proc_output, 'First report', 'dock_planner')

    def test_b_waits(self, proc_output):
        proc_output.assertWaitFor('First report', process='dock_planner', timeout=TIMEOUT)

    def test_c_reads_once(self, proc_output):  # the same check as test_a, run last
        launch_testing.asserts.assertInStderr(proc_output, 'First report', 'dock_planner')
# [END reads_once]
