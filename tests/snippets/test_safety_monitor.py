"""The capstone's safety monitor decides on each command from its latest wall
reading, and a wall stop holds until the wall is `release_margin` further than
`stop_distance`: noisy readings around the limit must not let a stopped robot
creep towards the wall (CI saw the launch_pytest wall test of lesson 7.3 fail
so, with the wall sensor's 0.01 m of noise).

The node runs in a child process of the built workspace; its readings and
commands are handed to its callbacks directly, so no ROS traffic is involved.
"""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

HANG_GUARD = 60  # seconds; only stops a hung child, never a speed limit

DECISIONS = """
import json
import sys

import rclpy
from capstone_interfaces.msg import WallReading
from capstone_robot.safety_monitor import SafetyMonitor
from geometry_msgs.msg import Twist

rclpy.init(args=['--ros-args', *sys.argv[1:]])
monitor = SafetyMonitor()
decisions = []
for ahead in json.loads(input()):
    monitor.on_reading(WallReading(ahead=ahead, nearest=ahead))
    forward = Twist()
    forward.linear.x = 1.0
    decisions.append(monitor.why_stop(forward))
print(json.dumps(decisions))
monitor.destroy_node()
rclpy.shutdown()
"""


def _reasons(ros_env: dict[str, str], readings: list[float], *ros_args: str
             ) -> list[str | None]:
    """For each wall reading in turn: why a forward command after it is held back (None:
    it passes)."""
    result = subprocess.run([sys.executable, '-c', DECISIONS, *ros_args], env=ros_env,
                            input=json.dumps(readings), text=True, capture_output=True,
                            timeout=HANG_GUARD, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    return json.loads(result.stdout.splitlines()[-1])


def _held(ros_env: dict[str, str], readings: list[float], *ros_args: str) -> list[bool]:
    return [reason is not None for reason in _reasons(ros_env, readings, *ros_args)]


def test_a_wall_stop_holds_through_readings_just_outside_the_limit(ros_env):
    # stop_distance 0.8, release_margin 0.1 (the code's defaults)
    readings = [2.0, 0.85, 0.79, 0.81, 0.8, 0.89, 0.91, 0.85, 0.79]
    assert _held(ros_env, readings) == [False, False, True, True, True, True, False, False,
                                        True]


@pytest.mark.parametrize('margin, readings, held', [
    ('0.0', [0.79, 0.85], [True, False]),
    ('0.5', [0.79, 1.2], [True, True]),
], ids=['no margin', 'a wide margin'])
def test_release_margin_is_a_parameter(ros_env, margin, readings, held):
    assert _held(ros_env, readings, '-p', f'release_margin:={margin}') == held


def test_the_reason_names_the_limit_the_reading_was_judged_by(ros_env):
    assert _reasons(ros_env, [0.79, 0.85]) == ['wall 0.79 m ahead (limit 0.80 m)',
                                               'wall 0.85 m ahead (limit 0.90 m)']
