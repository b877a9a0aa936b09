"""Exercise 7.3.1: a fault test for the capstone.

    launch_test src/my_ws_exercises/test/test_ex73_capstone_fault.py

The check runs this file against the working capstone and against broken
versions of capstone_bringup: it must pass on the first and fail on each of
the others.
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


@pytest.mark.launch_test
def generate_test_description():
    """capstone.launch.py with one robot, as users start it."""
    system = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('capstone_bringup'), 'launch', 'capstone.launch.py'])),
        launch_arguments={'robot_count': '1'}.items())
    # TODO: record why the launch shuts down (RegisterEventHandler(OnShutdown(...)))
    #       and hand the record to the tests: return (description, {'name': value})
    return launch.LaunchDescription([system, launch_testing.actions.ReadyToTest()])


class TestCapstoneFault(unittest.TestCase):
    """Active tests: they run while the system runs."""

    # TODO: wait until the system works, then kill turtle1's safety monitor
    #       (os.kill(proc_info['safety_monitor'].pid, signal.SIGKILL)) and wait
    #       for the system's reaction


# TODO: a post-shutdown test class (@launch_testing.post_shutdown_test()) that
#       checks why the launch shut down and how the other processes ended
