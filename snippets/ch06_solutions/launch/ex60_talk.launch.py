"""Exercise 6.0.1: your two terminals in one file.

    ros2 launch my_ws_exercises ex60_talk.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # terminal 1: ros2 run my_robot_pkg data_processor
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        # terminal 2: ros2 run my_robot_pkg sensor_publisher
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
    ])
