"""Lesson 6.15, pitfall: a test that hears another system on its domain.

    launch_test topic_only.py system:=<launch file>

It waits for messages on /battery_low, which is right, but any node of the
domain may publish them: another copy of the system started in the same
ROS_DOMAIN_ID makes it pass whatever its own system does.
"""
import unittest

import launch
import launch_testing.actions
import pytest
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_testing_ros import WaitForTopics
from std_msgs.msg import Bool

TIMEOUT = 15.0  # seconds; ends the wait when nothing comes


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        DeclareLaunchArgument('system', description='The launch file under test'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(LaunchConfiguration('system'))),
        launch_testing.actions.ReadyToTest(),
    ])


# [START topic_only]
class TestDockWatch(unittest.TestCase):

    def test_battery_low_published(self):
        with WaitForTopics([('battery_low', Bool)], timeout=TIMEOUT) as waiter:
            self.assertIn('battery_low', waiter.topics_received())
# [END topic_only]
