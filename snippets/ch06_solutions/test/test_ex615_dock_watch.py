"""Exercise 6.15.1: a launch test of dock_watch_pkg's dock_watch_v2.launch.py.

    launch_test src/my_ws_exercises/test/test_ex615_dock_watch.py

The check runs this file against the working system and against broken
versions of dock_watch_pkg: it must pass on the first and fail on each of
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

TIMEOUT = 15.0  # seconds; ends a wait that would hang, never a speed limit


@pytest.mark.launch_test
def generate_test_description():
    """dock_watch_v2.launch.py with its default arguments, as users start it."""
    system = IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution(
        [FindPackageShare('dock_watch_pkg'), 'launch', 'dock_watch_v2.launch.py'])))
    return launch.LaunchDescription([system, launch_testing.actions.ReadyToTest()])


# [START tests]
class TestDockWatch(unittest.TestCase):
    """Active tests: they run while the system runs."""

    def test_chain_connected(self, proc_output):
        # the planner logs this on its first /battery_low message: sim -> monitor -> planner
        proc_output.assertWaitFor('First report: battery ok', timeout=TIMEOUT)


@launch_testing.post_shutdown_test()
class TestDockWatchShutdown(unittest.TestCase):
    """Post-shutdown tests: every process ran until the launch stopped it."""

    def test_exit_codes(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)
# [END tests]
