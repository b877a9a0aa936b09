# Mistake: the data processor is left out, so the controller waits on /distance_filtered for data
#   that never comes.
# Verdict names: /data_processor is not in the graph
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
            executable='robot_controller',
            name='robot_controller',
            output='screen',
        ),
    ])
