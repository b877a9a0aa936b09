"""Exercise 6.5.1: two namespaced sensors feed one processor through /ranges.

    ros2 launch ch06_solutions ex65_two_sensors.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # The leading / makes /ranges absolute: the namespace is not put in
        # front of it, so both sensors leave their namespaces for one topic.
        Node(package='my_robot_pkg', executable='sensor_publisher', namespace='front',
             remappings=[('distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', namespace='rear',
             remappings=[('distance', '/ranges')], output='screen'),
        # No namespace here, so 'ranges' and '/ranges' are the same topic.
        Node(package='my_robot_pkg', executable='data_processor',
             remappings=[('distance', '/ranges')], output='screen'),
    ])
