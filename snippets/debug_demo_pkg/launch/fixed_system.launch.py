"""The system of broken_system.launch.py with its four faults fixed.

    ros2 launch debug_demo_pkg fixed_system.launch.py

Each sensor's Node action differs from the broken file in one place.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='debug_demo_pkg',
            executable='obstacle_monitor',
            name='obstacle_monitor',
            parameters=[{'sensors': ['front', 'rear', 'left', 'right']}],
            output='screen',
        ),
        # [START front]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='front_sensor',
            remappings=[('range', 'range/front')],  # was 'range_front'
            output='screen',
        ),
        # [END front]
        # [START rear]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',  # was 'legacy_range_sensor' (Float64)
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
            parameters=[{'reliability': 'reliable'}],  # was 'best_effort'
            output='screen',
        ),
        # [END left]
        # [START right]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='right_sensor',
            remappings=[('range', 'range/right')],
            # no additional_env: the sensor joins the launch's own ROS_DOMAIN_ID
            output='screen',
        ),
        # [END right]
    ])
