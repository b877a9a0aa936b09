# Mistake: the file name sensor_publisher.py instead of the executable sensor_publisher
# Verdict names: executable 'sensor_publisher.py' not found
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher.py', output='screen'),
    ])
