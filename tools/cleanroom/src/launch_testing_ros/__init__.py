"""Clean-room implementation of the ROS 2 Jazzy `launch_testing_ros` helpers used by
launch tests (WaitForTopics, LaunchTestRunner), from the documentation only."""
from .test_runner import LaunchTestRunner
from .wait_for_topics import WaitForTopics

__all__ = ['LaunchTestRunner', 'WaitForTopics']
