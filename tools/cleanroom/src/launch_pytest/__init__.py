"""Clean-room implementation of ROS 2 Jazzy `launch_pytest`.

A pytest plugin: `@launch_pytest.fixture` gives a launch description,
`@pytest.mark.launch(fixture=..., shutdown=...)` runs a test against it while
it runs (or after it shut down), and `launch_pytest.tools` waits for process
start, output and exit.  Written from the launch_pytest documentation only.
"""
from . import actions, tools
from .fixture import fixture

__all__ = ['actions', 'fixture', 'tools']
