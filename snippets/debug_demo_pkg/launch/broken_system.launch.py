"""Four range sensors and a monitor: broken on purpose, in four ways.

    ros2 launch debug_demo_pkg broken_system.launch.py

Every process starts and nothing crashes, yet the monitor hears none
of its four sensors.  Lesson 6.7 finds each fault with the ROS 2 tools;
fixed_system.launch.py is the same system repaired.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START monitor]
        Node(
            package='debug_demo_pkg',
            executable='obstacle_monitor',
            name='obstacle_monitor',
            parameters=[{'sensors': ['front', 'rear', 'left', 'right']}],
            output='screen',
        ),
        # [END monitor]
        # [START front]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='front_sensor',
            remappings=[('range', 'range_front')],
            output='screen',
        ),
        # [END front]
        # [START rear]
        Node(
            package='debug_demo_pkg',
            executable='legacy_range_sensor',
            name='rear_sensor',
            remappings=[('range', 'range/rear')],
            output='screen',
        ),
        # [END rear]
        # [START left]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='left_sensor',
            remappings=[('range', 'range/left')],
            parameters=[{'reliability': 'best_effort'}],
            output='screen',
        ),
        # [END left]
        # [START right]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='right_sensor',
            remappings=[('range', 'range/right')],
            additional_env={'ROS_DOMAIN_ID': '101'},
            output='screen',
        ),
        # [END right]
    ])
