"""A mistake: shell syntax in a command that runs without a shell.

    ros2 launch my_robot_pkg process_no_shell.launch.py
"""
from launch import LaunchDescription
from launch.actions import ExecuteProcess


def generate_launch_description():
    return LaunchDescription([
        # [START command]
        ExecuteProcess(
            cmd=['echo', 'robot $ROBOT_NAME works in $(pwd)'],  # no shell=True
            cwd='/tmp',
            additional_env={'ROBOT_NAME': 'alpha'},
            name='greeter',
            output='screen',
        ),
        # [END command]
    ])
