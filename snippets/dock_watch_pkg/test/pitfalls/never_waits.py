"""Lesson 6.15, pitfall: a test that passes because it never waited.

    launch_test never_waits.py system:=<launch file>

It reads the output collected so far, at once: right after the start
nothing has been said yet, so there is nothing to object to.  It passes on
a broken system as well as on a working one.
"""
import unittest

import launch
import launch_testing.actions
import pytest
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        DeclareLaunchArgument('system', description='The launch file under test'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(LaunchConfiguration('system'))),
        launch_testing.actions.ReadyToTest(),
    ])


# [START never_waits]
class TestDockWatch(unittest.TestCase):

    def test_no_errors_logged(self, proc_output):
        for output in proc_output:  # only what was said until now: nothing, yet
            self.assertNotIn('ERROR', output.text.decode())
# [END never_waits]

