"""Exercise 7.3.1: a fault test for the capstone.

    launch_test src/my_ws_exercises/test/test_ex73_capstone_fault.py

The check runs this file against the working capstone and against broken
versions of capstone_bringup: it must pass on the first and fail on each of
the others.
"""
import os
import signal
import threading
import unittest

import launch
import launch_testing.actions
import launch_testing.asserts
import pytest
from capstone_interfaces.msg import WallReading
from launch.actions import IncludeLaunchDescription, RegisterEventHandler
from launch.event_handlers import OnShutdown
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from launch_testing_ros import WaitForTopics

TIMEOUT = 30.0  # seconds; ends a wait that would hang, never a speed limit


# [START description]
@pytest.mark.launch_test
def generate_test_description():
    """capstone.launch.py with one robot, as users start it, and why it shuts down."""
    system = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('capstone_bringup'), 'launch', 'capstone.launch.py'])),
        launch_arguments={'robot_count': '1'}.items())
    reasons = []
    shut_down = threading.Event()

    def record(event, context):
        reasons.append(event.reason)
        shut_down.set()
    return launch.LaunchDescription([
        system,
        RegisterEventHandler(OnShutdown(on_shutdown=record)),
        launch_testing.actions.ReadyToTest(),
    ]), {'reasons': reasons, 'shut_down': shut_down}
# [END description]


# [START tests]
class TestCapstoneFault(unittest.TestCase):
    """Active test: the system works, then the fault, then the reaction."""

    def test_safety_monitor_dies(self, proc_info, shut_down):
        # the system works: the wall sensor measures (and the monitor reads it)
        with WaitForTopics([('/turtle1/wall_reading', WallReading)], timeout=TIMEOUT):
            pass
        os.kill(proc_info['safety_monitor'].pid, signal.SIGKILL)  # the fault: a crash
        self.assertTrue(shut_down.wait(TIMEOUT), 'the launch did not shut down')


@launch_testing.post_shutdown_test()
class TestCapstoneReaction(unittest.TestCase):
    """Post-shutdown tests: why it ended, and how the other processes ended."""

    def test_shut_down_because_of_the_safety_monitor(self, reasons):
        self.assertEqual(reasons[0], 'the safety monitor of turtle1 exited')

    def test_other_processes_stopped_cleanly(self, proc_info):
        for process in proc_info.processes():
            if 'safety_monitor' not in process.process_details['name']:
                launch_testing.asserts.assertExitCodes(proc_info, process=process)
# [END tests]
