"""Restart a node that dies, with respawn=True and respawn_delay.

    ros2 launch my_robot_pkg events_respawn.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START nodes]
        Node(
            package='events_demo_pkg',
            executable='flaky_sensor',
            parameters=[{'warmup': 0.5, 'crash_after': 3}],  # dies after 3 readings
            output='screen',
            respawn=True,       # start it again whenever it exits
            respawn_delay=2.0,  # seconds to wait before each restart
        ),
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        # [END nodes]
    ])
