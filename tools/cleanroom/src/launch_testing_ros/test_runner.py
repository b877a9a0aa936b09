"""LaunchTestRunner for ROS launch tests (the same runner as launch_testing's)."""
from launch_testing.test_runner import LaunchTestRunner as _BaseRunner


class LaunchTestRunner(_BaseRunner):
    """Runs launch tests that start ROS nodes."""
