"""A mistake: FindExecutable for a program that is not installed.

    ros2 launch my_robot_pkg process_missing_executable.launch.py
"""
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch.substitutions import FindExecutable


def generate_launch_description():
    return LaunchDescription([
        # [START command]
        ExecuteProcess(
            cmd=[FindExecutable(name='rosbag_recorder'), '--all'],
            output='screen',
        ),
        # [END command]
    ])
