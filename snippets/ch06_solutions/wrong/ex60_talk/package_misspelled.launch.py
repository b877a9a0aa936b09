# Mistake: the package written my_robot instead of my_robot_pkg
# Verdict names: package 'my_robot' not found
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot', executable='sensor_publisher', output='screen'),
    ])
