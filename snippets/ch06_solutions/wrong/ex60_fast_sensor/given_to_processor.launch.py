# Mistake: the setting given to the processor's Node, which has no publish_rate (it is ignored)
# Verdict names: /sensor_publisher started publishing at 2.0 Hz
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             parameters=[{'publish_rate': 5.0}]),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
    ])
