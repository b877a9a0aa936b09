"""Lesson 6.14: the first launch file written for specs/dock_watch.spec.yaml.

It has two mistakes the static check finds before anything runs (the lesson
shows the report, then dock_watch.launch.py, which fixes both):
the threshold written as a percentage, and the rate argument's default
written '2', which arrives at the node as the integer 2.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # [START attempt]
    return LaunchDescription([
        DeclareLaunchArgument('battery_rate', default_value='2',
                              description='Battery states per second (Hz)'),
        DeclareLaunchArgument('dock_x', default_value='0.0', description='Dock x in map (m)'),
        DeclareLaunchArgument('dock_y', default_value='0.0', description='Dock y in map (m)'),
        Node(package='dock_watch_pkg', executable='battery_sim', name='battery_sim',
             parameters=[{'publish_rate': LaunchConfiguration('battery_rate')}]),
        Node(package='dock_watch_pkg', executable='battery_monitor', name='battery_monitor',
             parameters=[{'low_threshold': 20.0}]),  # "low at 20 %"
        Node(package='dock_watch_pkg', executable='dock_planner', name='dock_planner',
             parameters=[{'dock_x': LaunchConfiguration('dock_x'),
                          'dock_y': LaunchConfiguration('dock_y'), 'frame_id': 'map'}]),
    ])
    # [END attempt]
