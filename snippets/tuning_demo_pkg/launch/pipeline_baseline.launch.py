"""The camera pipeline as first written: camera, detector, image statistics
and a monitor, each in its own process.

    ros2 launch tuning_demo_pkg pipeline_baseline.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='tuning_demo_pkg',
            executable='camera',
            name='camera',
            parameters=[{
                'width': 1280,
                'height': 720,
                'fps': 30.0,
                'reliability': 'reliable',
                'depth': 100,
            }],
            output='screen',
        ),
        Node(
            package='tuning_demo_pkg',
            executable='detector',
            name='detector',
            parameters=[{
                'detect_rate': 5.0,
                'reliability': 'reliable',
                'depth': 100,
            }],
            output='screen',
        ),
        Node(
            package='tuning_demo_pkg',
            executable='image_stats',
            name='image_stats',
            parameters=[{'reliability': 'reliable', 'depth': 100}],
            output='screen',
        ),
        Node(
            package='tuning_demo_pkg',
            executable='monitor',
            name='monitor',
            output='screen',
        ),
    ])
