"""Two distance sensors, one processor: remapping joins them on one topic.

    ros2 launch my_robot_pkg remap_two_sensors.launch.py

Each sensor publishes on "distance" in its code.  The remapping
('distance', 'ranges') makes both publish on /ranges instead, and the
same remapping makes the processor read /ranges.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START sensors]
        Node(package='my_robot_pkg', executable='sensor_publisher', name='front_sensor',
             remappings=[('distance', 'ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', name='rear_sensor',
             remappings=[('distance', 'ranges')], output='screen'),
        # [END sensors]
        # [START processor]
        Node(package='my_robot_pkg', executable='data_processor',
             remappings=[('distance', 'ranges')], output='screen'),
        # [END processor]
    ])
