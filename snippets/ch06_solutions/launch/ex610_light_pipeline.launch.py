"""Exercise 6.10.1: the pipeline within its budget.

    ros2 launch my_ws_exercises ex610_light_pipeline.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # Camera and detector in one process; no name=, which would give
        # both nodes the same name.
        Node(
            package='tuning_demo_pkg',
            executable='pipeline',
            parameters=[{
                'width': 640,
                'height': 480,
                'fps': 10.0,         # at most 10, and twice detect_rate
                'detect_rate': 5.0,
            }],
            output='screen',
        ),
        # No image_stats: the results do not need it.
        Node(
            package='tuning_demo_pkg',
            executable='monitor',
            name='monitor',
            output='screen',
        ),
    ])
