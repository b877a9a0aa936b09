# Mistake: publish_rate given as 5, an integer, for a float setting (the sensor refuses it and dies)
# Verdict names: expecting type 'DOUBLE'
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'publish_rate': 5}]),
    ])
