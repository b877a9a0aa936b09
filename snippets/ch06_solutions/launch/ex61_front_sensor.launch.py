"""Exercise 6.1.2: the same program, started under another node name.

    ros2 launch ch06_solutions ex61_front_sensor.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',  # the program stays the same...
            name='front_sensor',            # ...the node in the graph is renamed
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
        ),
    ])
