"""Lesson 6.15: the system's nodes under launch_pytest, with the running spec check.

launch_pytest starts the launch description of a fixture for the tests
marked with it; launch_pytest.tools waits for a process's start, output or
exit, given its action.  The fixture starts the three nodes itself, with the
values dock_watch_v2's spec asks for, so these tests check the nodes and
the spec, not the launch file: test_dock_watch_spec.py reads that one.  The
spec check asks the running graph, so it waits for the planner's first
report first: before that, the chain may not be connected yet.
"""
from pathlib import Path

import launch
import launch_pytest
import launch_ros.actions
import pytest
import speccheck
from ament_index_python.packages import get_package_share_directory
from launch_pytest.tools import process as process_tools

TIMEOUT = 60.0  # seconds; only ends a test that would hang, never a speed limit
SPEC = Path(get_package_share_directory('dock_watch_pkg')) / 'specs' / 'dock_watch_v2.spec.yaml'


# [START fixture]
def node(executable: str, **parameters) -> launch_ros.actions.Node:
    """One node of the system, with its output kept for the tests to read."""
    return launch_ros.actions.Node(package='dock_watch_pkg', executable=executable,
                                   name=executable, parameters=[parameters],
                                   cached_output=True)


@pytest.fixture(scope='module')
def planner():
    return node('dock_planner', dock_x=0.0, dock_y=0.0, frame_id='map')


@launch_pytest.fixture(scope='module')  # one launch for all the tests of this file
def dock_watch(planner):
    """dock_watch_v2's nodes with the values its spec asks for."""
    return launch.LaunchDescription([
        node('battery_sim', publish_rate=5.0),
        node('battery_monitor', low_threshold=0.25),
        planner,
        launch_pytest.actions.ReadyToTest(),
    ])
# [END fixture]


def first_report(text: str) -> bool:
    """The planner's first /battery_low message arrived: the whole chain is connected."""
    return 'First report: battery ok' in text


# [START tests]
@pytest.mark.launch(fixture=dock_watch)
async def test_chain_connected(planner, launch_context):
    await process_tools.wait_for_start(launch_context, planner, timeout=TIMEOUT)
    assert await process_tools.wait_for_stderr(launch_context, planner, first_report,
                                               timeout=TIMEOUT)


@pytest.mark.launch(fixture=dock_watch)
def test_running_system_meets_spec(planner, launch_context):
    assert process_tools.wait_for_stderr_sync(launch_context, planner, first_report,
                                              timeout=TIMEOUT)
    speccheck.check_live(speccheck.load_spec(SPEC), window=3.0).assert_ok()


@pytest.mark.launch(fixture=dock_watch)
def test_planner_ends_cleanly(planner, launch_context):
    # stopped before it is up, a node dies of the signal: wait until it works first
    assert process_tools.wait_for_stderr_sync(launch_context, planner, first_report,
                                              timeout=TIMEOUT)
    yield  # the code after yield runs once the launch has been shut down
    assert planner.return_code == 0
# [END tests]
