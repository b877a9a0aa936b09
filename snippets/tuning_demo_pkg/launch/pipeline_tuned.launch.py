"""The camera pipeline after measuring (lesson 6.10): only the changes that
measurably helped, and nothing the detector or the monitor needs is lost.

    ros2 launch tuning_demo_pkg pipeline_tuned.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START pipeline]
        # Camera and detector in one process (executable pipeline): one Python
        # process less. No name=: it would give both nodes the same name.
        Node(
            package='tuning_demo_pkg',
            executable='pipeline',
            parameters=[{
                'width': 1280,
                'height': 720,
                'fps': 10.0,         # two frames per detection at detect_rate 5.0
                'detect_rate': 5.0,
                # reliability and depth stay the nodes' defaults (reliable, 100):
                # best effort lost frames, depth 1 saved nothing measurable
            }],
            output='screen',
        ),
        # [END pipeline]
        # No image_stats: it received every frame only to log its size.
        Node(
            package='tuning_demo_pkg',
            executable='monitor',
            name='monitor',
            output='screen',
        ),
    ])
