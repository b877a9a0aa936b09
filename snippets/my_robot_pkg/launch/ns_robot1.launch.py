"""The sensor and the data processor of one robot, in the namespace robot1.

    ros2 launch my_robot_pkg ns_robot1.launch.py

The nodes become /robot1/sensor_publisher and /robot1/data_processor, and
their relative topic names follow: /robot1/distance, /robot1/distance_filtered.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START nodes]
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            namespace='robot1',   # no leading /: put under the namespace around it
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            namespace='robot1',
            output='screen',
        ),
        # [END nodes]
    ])
