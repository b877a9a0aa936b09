"""Exercise 6.0.2: a faster sensor.

The same two nodes as in Exercise 6.0.1.  Make the sensor publish 5
readings a second instead of 2: its setting (a parameter) is publish_rate,
in readings per second, a float.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex60_fast_sensor.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        # TODO: give the sensor publish_rate 5.0 (see the hint in the lesson)
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
    ])
