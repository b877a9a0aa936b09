"""Lesson 6.15: dock_watch_v2.launch.py under launch_testing.

Run it with `launch_test test/test_dock_watch_launch.py`, with `pytest`, or
with `colcon test`.  The launch file is the one the package installs, so the
test checks what users start; its arguments make the battery low after a
few seconds (threshold 0.95 on a full battery draining 0.01 per second), so
the whole chain, dock goal included, is tested in one short run.
"""
import unittest

import launch
import launch_testing.actions
import launch_testing.asserts
import pytest
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from launch_testing_ros import WaitForTopics
from sensor_msgs.msg import BatteryState
from std_msgs.msg import Bool

LAUNCH_FILE = 'dock_watch_v2.launch.py'
TIMEOUT = 60.0  # seconds; only ends a test that would hang, never a speed limit


# [START description]
@pytest.mark.launch_test
def generate_test_description():
    system = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('dock_watch_pkg'), 'launch', LAUNCH_FILE])),
        launch_arguments={'low_threshold': '0.95', 'dock_x': '2.5'}.items())
    return launch.LaunchDescription([system, launch_testing.actions.ReadyToTest()])
# [END description]


# [START active]
class TestDockWatch(unittest.TestCase):
    """Active tests: they run while the system runs, each waiting for a state."""

    def test_chain_connected(self, proc_output):
        # dock_planner logs this on its first /battery_low message
        proc_output.assertWaitFor('First report: battery', timeout=TIMEOUT)

    def test_topics_carry_messages(self):
        with WaitForTopics([('battery_state', BatteryState), ('battery_low', Bool)],
                           timeout=TIMEOUT) as waiter:
            self.assertEqual(waiter.topics_received(), {'battery_state', 'battery_low'})

    def test_goes_to_the_dock(self, proc_output):
        # threshold 0.95: low after about 5 s; the planner names the dock it sends
        proc_output.assertWaitFor('Battery low: heading to the dock at (2.5, 0.0)',
                                  timeout=TIMEOUT)
# [END active]


# [START post_shutdown]
@launch_testing.post_shutdown_test()
class TestDockWatchShutdown(unittest.TestCase):
    """Post-shutdown tests: they run once every process has ended."""

    def test_exit_codes(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)
# [END post_shutdown]
