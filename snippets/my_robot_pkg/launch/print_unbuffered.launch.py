"""Two ways to see a node's print() output as it happens.

    ros2 launch my_robot_pkg print_unbuffered.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START nodes]
        Node(
            package='my_robot_pkg',
            executable='print_counter',
            name='tty_counter',
            output='screen',
            emulate_tty=True,  # the node writes to a pseudo-terminal, not a pipe
        ),
        Node(
            package='my_robot_pkg',
            executable='print_counter',
            name='unbuffered_counter',
            output='screen',
            additional_env={'PYTHONUNBUFFERED': '1'},  # Python: never hold output back
        ),
        # [END nodes]
    ])
