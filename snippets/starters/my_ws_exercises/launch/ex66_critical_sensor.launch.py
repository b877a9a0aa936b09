"""Exercise 6.6.1: start the processor when the sensor is ready; stop everything when it dies.

The sensor is slow to calibrate: data_processor must start only once
sensor_publisher has logged "Publishing distance readings" (it is ready).
Without the sensor the robot is blind: when the sensor's process exits, for
any reason, the whole launch must shut down.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex66_critical_sensor.launch.py
"""
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler  # noqa: F401  (you will need them)
from launch.event_handlers import OnProcessExit, OnProcessIO  # noqa: F401
from launch.events import Shutdown  # noqa: F401
from launch_ros.actions import Node


def generate_launch_description():
    sensor = Node(package='my_robot_pkg', executable='sensor_publisher', output='screen')
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')
    return LaunchDescription([
        sensor,
        # TODO: start the processor only when the sensor's output says it is ready,
        #       not together with the sensor
        processor,
        # TODO: when the sensor's process exits, shut the whole launch down
    ])
