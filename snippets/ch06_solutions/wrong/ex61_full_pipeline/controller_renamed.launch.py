# Mistake: the controller is started under another node name (controller), so /robot_controller
#   is not in the graph.
# Verdict names: /robot_controller is not in the graph (nodes: /controller
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
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='controller',
            output='screen',
        ),
    ])
