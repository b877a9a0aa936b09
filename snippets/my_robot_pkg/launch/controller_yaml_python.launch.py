"""controller_yaml.launch.py with the path worked out in plain Python.

    ros2 launch my_robot_pkg controller_yaml_python.launch.py

get_package_share_directory() runs at once, while generate_launch_description()
builds the description, and returns an ordinary string.
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # [START params_file]
    params_file = os.path.join(
        get_package_share_directory('my_robot_pkg'),  # a str, known right now
        'config',
        'robot_params.yaml',
    )
    # [END params_file]
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[params_file],
        ),
    ])
