"""A launch file with a common mistake: the Python file's name as the executable.

    ros2 launch my_robot_pkg mistake_executable_name.launch.py

`executable` is the name of an entry point in setup.py (`sensor_publisher`),
not the name of the source file (`sensor_publisher.py`).  Lesson 6.1 shows
the error launch reports.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher.py',   # MISTAKE: the entry point is 'sensor_publisher'
            name='sensor_publisher',
            output='screen',
        ),
        # [END node]
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
        ),
    ])
