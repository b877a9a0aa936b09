"""Lesson 7.3: the capstone's safety behaviour under launch_pytest.

Each test gets its own launch (function-scoped fixtures: one turtlesim at a
time) and watches the turtle from outside, as an observer would, through
/turtle1/pose: the safety monitor must stop a turtle driven at a wall
before it reaches the wall, and when the wall sensor crashes the robot must
hold still until launch has started the sensor again (respawn), then drive
on.  The launch files are the ones the package installs.
"""
import math
import os
import signal
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import launch
import launch_pytest
import pytest
import rclpy
import yaml
from ament_index_python.packages import get_package_share_directory
from capstone_interfaces.msg import WallReading
from launch.actions import IncludeLaunchDescription, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import qos_profile_sensor_data
from turtlesim.msg import Pose

TIMEOUT = 60.0  # seconds; only ends a test that would hang, never a speed limit
WORLD = 11.088889  # metres: turtlesim's square
BEYOND_THE_WALL = Path(__file__).parent / 'beyond_the_wall.yaml'
DEFAULTS = Path(get_package_share_directory('capstone_bringup')) / 'config' / 'defaults.yaml'
STOP_DISTANCE = yaml.safe_load(DEFAULTS.read_text())[
    '/**/safety_monitor']['ros__parameters']['stop_distance']


class Starts:
    """The pid of every process start, by executable: a respawn is a second start."""

    def __init__(self) -> None:
        self.pids: dict[str, list[int]] = {}
        self._lock = threading.Lock()

    def record(self, event, context) -> None:
        executable = os.path.basename(event.cmd[0])
        with self._lock:
            self.pids.setdefault(executable, []).append(event.pid)

    def of(self, executable: str) -> list[int]:
        with self._lock:
            return list(self.pids.get(executable, []))


class Observer:
    """A ROS node of the test's own: the latest message of each topic it watches."""

    def __init__(self) -> None:
        self.context = rclpy.Context()
        rclpy.init(context=self.context)
        self.node = rclpy.create_node('capstone_test_observer', context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.messages: dict[str, list] = {}
        self._lock = threading.Lock()
        self._thread = threading.Thread(target=self._spin, daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        while self.context.ok():
            self.executor.spin_once(timeout_sec=0.1)

    def watch(self, message_type: type, topic: str) -> None:
        # best effort: hears a publisher of either reliability
        self.node.create_subscription(message_type, topic, lambda m: self._keep(topic, m),
                                      qos_profile_sensor_data)

    def _keep(self, topic: str, message: object) -> None:
        with self._lock:
            self.messages.setdefault(topic, []).append(message)

    def received(self, topic: str) -> list:
        with self._lock:
            return list(self.messages.get(topic, []))

    def wait_for(self, topic: str, condition: Callable[[object], bool], what: str,
                 after: int = 0) -> int:
        """The index of the first message from index ``after`` on that meets ``condition``."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            for index, message in enumerate(self.received(topic)[after:], start=after):
                if condition(message):
                    return index
            time.sleep(0.05)  # polling a state, not waiting for a time
        raise AssertionError(f'timed out waiting for {what} on {topic}')

    def close(self) -> None:
        self.executor.shutdown()
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)
        self._thread.join()


def include(launch_file: str, **arguments: str) -> IncludeLaunchDescription:
    return IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'launch', launch_file])),
        launch_arguments=arguments.items())


@pytest.fixture
def starts() -> Starts:
    return Starts()


@pytest.fixture
def observer() -> Iterator[Observer]:
    watcher = Observer()
    watcher.watch(Pose, '/turtle1/pose')
    yield watcher
    watcher.close()


# [START fixtures]
@launch_pytest.fixture
def driven_at_the_wall():
    """The simulator and turtle1, whose only waypoint lies beyond the right wall."""
    return launch.LaunchDescription([
        include('sim.launch.py'),
        include('robot.launch.py', robot='turtle1', robot_params=str(BEYOND_THE_WALL)),
        launch_pytest.actions.ReadyToTest(),
    ])


@launch_pytest.fixture
def patrolling(starts):
    """The capstone with one robot on its route; every process start is recorded."""
    return launch.LaunchDescription([
        include('capstone.launch.py', robot_count='1'),
        RegisterEventHandler(OnProcessStart(on_start=starts.record)),
        launch_pytest.actions.ReadyToTest(),
    ])
# [END fixtures]


def moving(pose: Pose) -> bool:
    return pose.linear_velocity != 0.0 or pose.angular_velocity != 0.0


# [START tests]
@pytest.mark.launch(fixture=driven_at_the_wall)
def test_safety_monitor_stops_the_turtle_before_the_wall(observer):
    topic = '/turtle1/pose'
    first = observer.wait_for(topic, lambda p: True, 'a first pose')
    start = observer.received(topic)[first]
    driving = observer.wait_for(topic, lambda p: p.x > start.x + 1.0, 'turtle1 driving',
                                after=first)
    stopped = observer.wait_for(topic, lambda p: p.linear_velocity == 0.0,
                                'turtle1 stopped', after=driving)
    pose = observer.received(topic)[stopped]
    assert abs(math.sin(pose.theta)) < 0.1, pose  # it drove straight at the right wall
    # it stops as soon as a reading says the wall is closer than stop_distance
    assert STOP_DISTANCE - 0.3 < WORLD - pose.x <= STOP_DISTANCE + 0.05, pose
    # ... and stays stopped, although its controller still drives towards the wall
    later = observer.wait_for(topic, lambda p: True, 'more poses', after=stopped + 50)
    assert observer.received(topic)[later].x == pytest.approx(pose.x, abs=0.01)


@pytest.mark.launch(fixture=patrolling)
def test_killed_wall_sensor_comes_back_while_the_robot_holds_still(starts, observer):
    topic = '/turtle1/pose'
    observer.watch(WallReading, '/turtle1/wall_reading')
    first = observer.wait_for(topic, moving, 'turtle1 on its route')
    [sensor] = starts.of('wall_sensor')
    os.kill(sensor, signal.SIGKILL)  # a crash
    # blind: the safety monitor lets no motion through
    held = observer.wait_for(topic, lambda p: not moving(p), 'turtle1 held', after=first)
    readings = len(observer.received('/turtle1/wall_reading'))
    observer.wait_for('/turtle1/wall_reading', lambda r: True, 'readings again',
                      after=readings)  # from the respawned sensor: launch started it again
    back = observer.wait_for(topic, moving, 'turtle1 driving again', after=held)
    poses = observer.received(topic)
    assert len(starts.of('wall_sensor')) == 2 and starts.of('wall_sensor')[1] != sensor
    still = poses[held]
    assert all(math.dist((p.x, p.y), (still.x, still.y)) < 0.01
               for p in poses[held:back]), 'turtle1 moved while its wall sensor was down'
# [END tests]
