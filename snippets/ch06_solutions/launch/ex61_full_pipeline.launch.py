"""Exercise 6.1.1: the whole robot from one launch file.

    ros2 launch ch06_solutions ex61_full_pipeline.launch.py

sensor_publisher -> /distance -> data_processor -> /distance_filtered
-> robot_controller -> /cmd_vel
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='sensor_publisher',
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
        ),
        # The new part: a third Node action, for the controller.
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
        ),
    ])
