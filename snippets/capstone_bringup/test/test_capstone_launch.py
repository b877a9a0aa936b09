"""Lesson 7.3: the capstone under launch_testing, with a fault planted in a run.

Run it with `launch_test test/test_capstone_launch.py`, with `pytest`, or
with `colcon test`.  The launch file is the one the package installs
(capstone.launch.py, one robot), so the test checks what users start.  The
active tests wait for the system to come up, then the last one plants the
fault: it kills turtle1's safety monitor, as a crash would.  The capstone
must react by shutting the whole launch down and saying why; the
post-shutdown tests read the exit codes and the reason.

Active tests run in the order of their names (unittest sorts them), so the
fault comes last: test_4_....  It returns as soon as the shutdown has begun,
while the nodes are still stopping: launch_testing reports a launch that has
ended before its active tests as 'Processes under test stopped before tests
completed'.
"""
import os
import signal
import threading
import unittest

import launch
import launch_testing.actions
import launch_testing.asserts
import pytest
from capstone_interfaces.msg import WallReading
from launch.actions import IncludeLaunchDescription, RegisterEventHandler
from launch.event_handlers import OnShutdown
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from launch_testing_ros import WaitForTopics

LAUNCH_FILE = 'capstone.launch.py'
ROBOT = 'turtle1'
TIMEOUT = 60.0  # seconds; only ends a test that would hang, never a speed limit
WORLD = 11.088889  # metres: turtlesim's square


class ShutdownWitness:
    """Records why the launch shut down; the test thread can wait for the first reason."""

    def __init__(self) -> None:
        self.reasons: list[str] = []
        self.began = threading.Event()

    def record(self, event, context) -> None:
        self.reasons.append(event.reason)
        self.began.set()


# [START description]
@pytest.mark.launch_test
def generate_test_description():
    system = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'launch', LAUNCH_FILE])),
        launch_arguments={'robot_count': '1'}.items())
    witness = ShutdownWitness()
    return launch.LaunchDescription([
        system,
        RegisterEventHandler(OnShutdown(on_shutdown=witness.record)),
        launch_testing.actions.ReadyToTest(),
    ]), {'witness': witness}
# [END description]


# [START active]
class TestCapstone(unittest.TestCase):
    """Active tests: they run while the system runs, each waiting for a state."""

    def test_1_robot_nodes_start(self, proc_info):
        for node in ('turtlesim_node', 'wall_sensor', 'pose_estimator', 'patrol_planner',
                     'controller', 'safety_monitor', 'mission_recorder'):
            proc_info.assertWaitForStartup(process=node, timeout=TIMEOUT)

    def test_2_wall_readings_flow(self):
        topic = f'/{ROBOT}/wall_reading'
        with WaitForTopics([(topic, WallReading)], timeout=TIMEOUT) as waiter:
            reading = waiter.received_messages(topic)[0]
        self.assertIn(reading.nearest_wall, ('left', 'right', 'bottom', 'top'))
        self.assertTrue(0.0 <= reading.nearest <= WORLD / 2 + 0.1, reading)

    def test_3_recorder_becomes_active(self, proc_output):
        # the lifecycle node logs this in on_activate, after launch configured it
        proc_output.assertWaitFor('Active: recording the mission',
                                  process='mission_recorder', timeout=TIMEOUT)

    def test_4_fault_safety_monitor_killed(self, proc_info, proc_output, witness):
        # It must be guarding first: stopped before it is up, any node dies of the signal.
        proc_output.assertWaitFor('Guarding: stop 0.80 m before a wall',
                                  process='safety_monitor', timeout=TIMEOUT)
        os.kill(proc_info['safety_monitor'].pid, signal.SIGKILL)  # a crash
        self.assertTrue(witness.began.wait(TIMEOUT), 'the launch did not shut down')
# [END active]


# [START post_shutdown]
@launch_testing.post_shutdown_test()
class TestCapstoneShutdown(unittest.TestCase):
    """Post-shutdown tests: they run once every process has ended."""

    def test_shutdown_names_the_safety_monitor(self, witness):
        self.assertEqual(witness.reasons[0], f'the safety monitor of {ROBOT} exited')

    def test_safety_monitor_died_of_the_fault(self, proc_info):
        self.assertEqual(proc_info['safety_monitor'].returncode, -signal.SIGKILL)

    def test_every_other_node_stopped_cleanly(self, proc_info):
        for process in proc_info.processes():
            if 'safety_monitor' not in process.process_details['name']:
                launch_testing.asserts.assertExitCodes(proc_info, process=process)
# [END post_shutdown]
