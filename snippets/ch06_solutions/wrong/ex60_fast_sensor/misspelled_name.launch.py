# Mistake: a setting the sensor does not have (rate, not publish_rate): silently ignored
# Verdict names: /sensor_publisher got publish_rate 2.0 (a float), expected 5.0
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'rate': 5.0}]),
    ])
