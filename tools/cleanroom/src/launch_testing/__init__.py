"""Clean-room implementation of ROS 2 Jazzy `launch_testing`.

Integration tests for launch files: a test file's `generate_test_description()`
is launched, its active `unittest.TestCase` classes run while the processes
are up, and its `post_shutdown_test()` classes after they stopped.  Written
from the launch_testing documentation and recorded Jazzy behaviour only.
"""
from .decorator import post_shutdown_test
from .io_handler import ActiveIoHandler, IoHandler
from .parametrize import parametrize
from .proc_info_handler import ActiveProcInfoHandler, ProcInfoHandler
from .ready_aggregator import ReadyAggregator
from .ready_to_test_action_timeout import ready_to_test_action_timeout

__all__ = [
    'ActiveIoHandler',
    'ActiveProcInfoHandler',
    'IoHandler',
    'ProcInfoHandler',
    'ReadyAggregator',
    'parametrize',
    'post_shutdown_test',
    'ready_to_test_action_timeout',
]
