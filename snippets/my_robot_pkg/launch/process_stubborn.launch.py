"""What Ctrl+C does to nodes that do not stop: SIGINT, then SIGTERM, then SIGKILL.

    ros2 launch my_robot_pkg process_stubborn.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START nodes]
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
        Node(
            package='events_demo_pkg',
            executable='stubborn_node',
            name='map_saver',
            parameters=[{'ignore_sigint': True}],
            output='screen',
            sigterm_timeout='2',  # SIGTERM 2 s after SIGINT (default 5)
            sigkill_timeout='2',  # SIGKILL 2 s after that (default 5)
        ),
        Node(
            package='events_demo_pkg',
            executable='stubborn_node',
            name='hung_driver',
            parameters=[{'ignore_sigint': True, 'ignore_sigterm': True}],
            output='screen',
            sigterm_timeout='2',
            sigkill_timeout='2',
        ),
        # [END nodes]
    ])
