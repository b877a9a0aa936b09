# Mistake: checks that the safety monitor exited: the fault itself, not the reaction
# Verdict names: passes on a system whose safety monitor's exit does not shut the launch down
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


class TestCapstoneFault(unittest.TestCase):
    """Active test: the system works, then the fault."""

    def test_safety_monitor_dies(self, proc_info):
        with WaitForTopics([('/turtle1/wall_reading', WallReading)], timeout=TIMEOUT):
            pass
        os.kill(proc_info['safety_monitor'].pid, signal.SIGKILL)
        proc_info.assertWaitForShutdown(process='safety_monitor', timeout=TIMEOUT)


@launch_testing.post_shutdown_test()
class TestCapstoneReaction(unittest.TestCase):
    """Post-shutdown test: the safety monitor was killed."""

    def test_safety_monitor_was_killed(self, proc_info):
        self.assertEqual(proc_info['safety_monitor'].returncode, -signal.SIGKILL)
