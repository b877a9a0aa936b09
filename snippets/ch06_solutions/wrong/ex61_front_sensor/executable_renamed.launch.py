# Mistake: the executable is renamed along with the node (executable='front_sensor'): there is no
#   such program.
# Verdict names: executable 'front_sensor' not found
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='front_sensor',
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
