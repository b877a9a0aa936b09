# Mistake: the executable is given as the source file name (sensor_publisher.py); the entry point
#   of setup.py is sensor_publisher.
# Verdict names: executable 'sensor_publisher.py' not found
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher.py',
            name='sensor_publisher',
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
        ),
    ])
