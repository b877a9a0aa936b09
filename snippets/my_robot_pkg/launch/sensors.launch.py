"""Start the sensor and the data processor together."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START nodes]
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            parameters=[{'publish_rate': 2.0}],
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            output='screen',
        ),
        # [END nodes]
    ])
