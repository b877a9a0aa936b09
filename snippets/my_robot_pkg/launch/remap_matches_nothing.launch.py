"""Common mistake: a remapping whose first name matches no name of the node.

    ros2 launch my_robot_pkg remap_matches_nothing.launch.py

Like remap_two_sensors.launch.py, but the processor's remapping says
"distances".  The processor has no topic of that name, so the rule changes
nothing, and nobody tells you: the processor still reads /distance.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', name='front_sensor',
             remappings=[('distance', 'ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', name='rear_sensor',
             remappings=[('distance', 'ranges')], output='screen'),
        # [START processor]
        Node(package='my_robot_pkg', executable='data_processor',
             remappings=[('distances', 'ranges')],   # typo: the topic is "distance"
             output='screen'),
        # [END processor]
    ])
