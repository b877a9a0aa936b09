# Mistake: the controller is left out, so nothing uses /distance_filtered and nobody publishes
#   /cmd_vel.
# Verdict names: /robot_controller is not in the graph
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
