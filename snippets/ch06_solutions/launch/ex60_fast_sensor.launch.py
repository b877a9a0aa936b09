"""Exercise 6.0.2: a faster sensor, 5 readings a second.

    ros2 launch my_ws_exercises ex60_fast_sensor.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'publish_rate': 5.0}]),  # 5.0, a float: the sensor declared 2.0
    ])
