# Mistake: the node keeps the program's name, /sensor_publisher, instead of front_sensor.
# Verdict names: /sensor_publisher is still in the graph
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
    ])
