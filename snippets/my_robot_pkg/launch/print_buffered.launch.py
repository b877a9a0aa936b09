"""A node that uses print(), started with output='screen' and nothing else.

    ros2 launch my_robot_pkg print_buffered.launch.py

Its printed lines arrive late, all at once: lesson 6.1 shows why.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='print_counter',
            output='screen',
        ),
        # [END node]
    ])
