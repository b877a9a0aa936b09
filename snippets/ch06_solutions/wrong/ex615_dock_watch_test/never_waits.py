# Mistake: the test reads the output once, at once, and never waits for the system
# Verdict names: passes on a system whose battery_monitor listens on the wrong topic
"""Exercise 6.15.1: a launch test of dock_watch_pkg's dock_watch_v2.launch.py.

    launch_test src/my_ws_exercises/test/test_ex615_dock_watch.py

The check runs this file against the working system and against broken
versions of dock_watch_pkg: it must pass on the first and fail on each of
the others.
"""
import unittest

import launch
import launch_testing.actions
import pytest
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


@pytest.mark.launch_test
def generate_test_description():
    """dock_watch_v2.launch.py with its default arguments, as users start it."""
    system = IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution(
        [FindPackageShare('dock_watch_pkg'), 'launch', 'dock_watch_v2.launch.py'])))
    return launch.LaunchDescription([system, launch_testing.actions.ReadyToTest()])


class TestDockWatch(unittest.TestCase):

    def test_no_errors_logged(self, proc_output):
        for output in proc_output:
            self.assertNotIn('ERROR', output.text.decode())
