# Mistake: two sensor_publisher processes are both named front_sensor: two nodes share one name.
# Verdict names: 2 processes run as the node /front_sensor
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='front_sensor',
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='front_sensor',
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
        ),
    ])
